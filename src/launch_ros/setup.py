from setuptools import find_packages, setup

package_name = 'launch_ros'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='ROS 2 specific launch actions and substitutions.',
    license='Apache-2.0',
    entry_points={
        # Imported by launch's front ends before parsing: registers <node>, <set_parameter>,
        # <push-ros-namespace>, <set_remap> and $(find-pkg-share), $(exec-in-pkg), ...
        'launch.frontend.launch_extension': [
            'launch_ros = launch_ros',
        ],
    },
)
