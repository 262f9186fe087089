from setuptools import find_packages, setup

package_name = 'ros2launch'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        # Adds `launch` to the `ros2` command (see ros2cli/cli.py).
        ('share/ament_index/resource_index/ros2cli.command', ['resource/commands/launch']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='The ros2 launch command.',
    license='Apache-2.0',
)
