from setuptools import find_packages, setup

package_name = 'quality_of_service_demo_py'

setup(
    name=package_name,
    version='0.33.5',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description="Stand-in for upstream's quality_of_service_demo_py.",
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'deadline = quality_of_service_demo_py.deadline:main',
            'incompatible_qos = quality_of_service_demo_py.incompatible_qos:main',
            'lifespan = quality_of_service_demo_py.lifespan:main',
            'liveliness = quality_of_service_demo_py.liveliness:main',
            'message_lost_listener = quality_of_service_demo_py.message_lost_listener:main',
            'qos_overrides_listener = quality_of_service_demo_py.qos_overrides_listener:main',
            'qos_overrides_talker = quality_of_service_demo_py.qos_overrides_talker:main',
        ],
    },
)
