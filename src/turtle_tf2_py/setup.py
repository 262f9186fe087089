from glob import glob

from setuptools import find_packages, setup

package_name = 'turtle_tf2_py'

setup(
    name=package_name,
    version='0.3.6',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch', glob('launch/*.launch.py')),
        ('share/' + package_name + '/rviz', glob('rviz/*.rviz')),
    ],
    install_requires=['setuptools'],
    extras_require={'test': ['pytest']},  # colcon test runs test/ with pytest
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='The tf2 tutorials with turtlesim (Python): broadcasters, listeners, frames.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'static_turtle_tf2_broadcaster = turtle_tf2_py.static_turtle_tf2_broadcaster:main',
            'turtle_tf2_broadcaster = turtle_tf2_py.turtle_tf2_broadcaster:main',
            'turtle_tf2_listener = turtle_tf2_py.turtle_tf2_listener:main',
            'fixed_frame_tf2_broadcaster = turtle_tf2_py.fixed_frame_tf2_broadcaster:main',
            'dynamic_frame_tf2_broadcaster = turtle_tf2_py.dynamic_frame_tf2_broadcaster:main',
            'turtle_tf2_listener_using_time = turtle_tf2_py.turtle_tf2_listener_using_time:main',
            'turtle_tf2_listener_time_travel = turtle_tf2_py.turtle_tf2_listener_time_travel:main',
        ],
    },
)
