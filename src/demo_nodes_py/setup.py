from setuptools import find_packages, setup

package_name = 'demo_nodes_py'
EXECUTABLES = {
    'talker': 'topics.talker',
    'listener': 'topics.listener',
    'talker_qos': 'topics.talker_qos',
    'listener_qos': 'topics.listener_qos',
    'listener_serialized': 'topics.listener_serialized',
    'add_two_ints_server': 'services.add_two_ints_server',
    'add_two_ints_client': 'services.add_two_ints_client',
    'add_two_ints_client_async': 'services.add_two_ints_client_async',
    'introspection': 'services.introspection',
    'async_param_client': 'parameters.async_param_client',
    'set_parameters_callback': 'parameters.set_parameters_callback',
    'matched_event_detect': 'events.matched_event_detect',
    'use_logger_service': 'logging.use_logger_service',
}

setup(
    name=package_name,
    version='0.33.5',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml', 'demo_nodes_py/parameters/params.yaml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description="Stand-in for upstream's demo_nodes_py: the Python demo nodes.",
    license='Apache-2.0',
    entry_points={
        'console_scripts': [f'{name} = {package_name}.{module}:main'
                            for name, module in EXECUTABLES.items()],
    },
)
