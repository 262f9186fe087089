from glob import glob

from setuptools import find_packages, setup

package_name = 'demo_nodes_cpp'
EXECUTABLES = {
    'talker': 'topics.talker',
    'listener': 'topics.listener',
    'listener_best_effort': 'topics.listener_best_effort',
    'talker_serialized_message': 'topics.talker_serialized_message',
    'listener_serialized_message': 'topics.listener_serialized_message',
    'add_two_ints_server': 'services.add_two_ints_server',
    'add_two_ints_client': 'services.add_two_ints_client',
    'add_two_ints_client_async': 'services.add_two_ints_client_async',
    'introspection_service': 'services.introspection_service',
    'introspection_client': 'services.introspection_client',
    'parameter_blackboard': 'parameter_blackboard',
    'list_parameters': 'parameters.list_parameters',
    'list_parameters_async': 'parameters.list_parameters:main_async',
    'set_and_get_parameters': 'parameters.set_and_get_parameters',
    'set_and_get_parameters_async': 'parameters.set_and_get_parameters:main_async',
    'parameter_events': 'parameters.parameter_events',
    'parameter_events_async': 'parameters.parameter_events:main_async',
    'parameter_event_handler': 'parameters.parameter_event_handler',
    'even_parameters_node': 'parameters.even_parameters_node',
    'set_parameters_callback': 'parameters.set_parameters_callback',
    'one_off_timer': 'timers.one_off_timer',
    'reuse_timer': 'timers.reuse_timer',
    'matched_event_detect': 'events.matched_event_detect',
    'use_logger_service': 'logging.use_logger_service',
}


def entry_point(name: str, target: str) -> str:
    module, _, function = target.partition(':')
    return f'{name} = {package_name}.{module}:{function or "main"}'


setup(
    name=package_name,
    version='0.33.5',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch/topics', glob('launch/topics/*_launch.*')),
        ('share/' + package_name + '/launch/services', glob('launch/services/*_launch.*')),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description="Stand-in for upstream's demo_nodes_cpp, in Python.",
    license='Apache-2.0',
    entry_points={
        'console_scripts': [entry_point(name, target) for name, target in EXECUTABLES.items()],
    },
)
