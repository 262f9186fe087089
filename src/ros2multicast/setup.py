from glob import glob

from setuptools import find_packages, setup

package_name = 'ros2multicast'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        # `ros2 multicast` (see ros2cli/cli.py).
        ('share/ament_index/resource_index/ros2cli.command',
         sorted(glob('resource/commands/*'))),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='ros2 multicast: send and receive one UDP multicast datagram on loopback.',
    license='Apache-2.0',
)
