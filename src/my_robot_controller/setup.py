from glob import glob

from setuptools import find_packages, setup

package_name = 'my_robot_controller'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch', glob('launch/*.launch.py')),
    ],
    install_requires=['setuptools'],
    extras_require={'test': ['pytest']},  # colcon test runs test/ with pytest
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='Tutorial nodes: AddTwoInts server and client, turtle_controller.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'add_two_ints_server = my_robot_controller.add_two_ints_server:main',
            'add_two_ints_client = my_robot_controller.add_two_ints_client:main',
            'turtle_controller = my_robot_controller.turtle_controller:main',
            'turtle_demo = my_robot_controller.demo_launch:main',
        ],
    },
)
