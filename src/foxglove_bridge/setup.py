from glob import glob

from setuptools import find_packages, setup

package_name = 'foxglove_bridge'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch', glob('launch/*.xml')),
    ],
    install_requires=['setuptools'],
    extras_require={'test': ['pytest']},  # colcon test runs test/ with pytest
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='A Foxglove WebSocket bridge for Foxglove (foxglove.sdk.v1) and Lichtblick '
                '(foxglove.websocket.v1) on one port.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'foxglove_bridge = foxglove_bridge.foxglove_bridge_node:main',
        ],
    },
)
