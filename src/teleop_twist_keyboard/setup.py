from setuptools import find_packages, setup

package_name = 'teleop_twist_keyboard'

setup(
    name=package_name,
    version='2.4.0',
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
    description='Generic keyboard teleop: key presses to geometry_msgs/Twist on cmd_vel.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'teleop_twist_keyboard = teleop_twist_keyboard.teleop_twist_keyboard:main',
        ],
    },
)
