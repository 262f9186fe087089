from glob import glob

from setuptools import setup

package_name = 'diffbot_bringup'

setup(
    name=package_name,
    version='0.1.0',
    packages=[],
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch', glob('launch/*.launch.py')),
        ('share/' + package_name + '/rviz', glob('rviz/*')),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='Launch the diffbot in a MuJoCo world with robot_state_publisher and RViz.',
    license='Apache-2.0',
)
