from glob import glob

from setuptools import find_packages, setup

package_name = 'ros2bag'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        # `ros2 bag` (see ros2cli/cli.py: commands come from this resource type).
        ('share/ament_index/resource_index/ros2cli.command',
         sorted(glob('resource/commands/*'))),
    ],
    install_requires=['setuptools'],
    extras_require={'test': ['pytest']},  # colcon test runs test/ with pytest
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='ros2 bag: record, play and inspect rosbag2 directories (MCAP, SQLite3).',
    license='Apache-2.0',
)
