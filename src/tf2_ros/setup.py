from setuptools import find_packages, setup

package_name = 'tf2_ros'

setup(
    name=package_name,
    version='0.36.4',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    extras_require={'test': ['pytest']},  # colcon test runs test/ with pytest
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='tf2 over ROS 2 in Python, with upstream tf2_ros API and executables.',
    license='BSD-3-Clause',
    entry_points={
        'console_scripts': [
            'buffer_server = tf2_ros.buffer_server:main',
            'static_transform_publisher = tf2_ros.static_transform_publisher:main',
            'tf2_echo = tf2_ros.tf2_echo:main',
            'tf2_monitor = tf2_ros.tf2_monitor:main',
        ],
    },
)
