from glob import glob

from setuptools import find_packages, setup

package_name = 'ros2pkg'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    package_data={package_name: ['templates/*/*']},
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        # `ros2 pkg` (see ros2cli/cli.py).
        ('share/ament_index/resource_index/ros2cli.command',
         sorted(glob('resource/commands/*'))),
    ],
    install_requires=['setuptools'],
    zip_safe=False,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='ros2 pkg: create, executables, list, prefix, xml.',
    license='Apache-2.0',
)
