from glob import glob

from setuptools import find_packages, setup

package_name = 'mujoco_sim'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/worlds', glob('worlds/*')),
        # Maps made from the worlds by world_to_map, for map_server (warehouse.yaml/.pgm).
        ('share/' + package_name + '/maps', glob('maps/*')),
    ],
    install_requires=['setuptools'],
    extras_require={'test': ['pytest']},  # colcon test runs test/ with pytest
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='A MuJoCo robot simulator bridged to ROS 2 as ros_gz bridges Gazebo.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'mujoco_sim = mujoco_sim.simulator:main',
            'world_to_map = mujoco_sim.world_to_map:main',
        ],
    },
)
