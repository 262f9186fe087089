from glob import glob

from setuptools import find_packages, setup

package_name = 'nav2_map_server'

setup(
    name=package_name,
    version='1.3.13',
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
    description="Nav2's map server and map saver in Python, with Nav2's map file format.",
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'map_server = nav2_map_server.map_server:main',
            'map_saver_server = nav2_map_server.map_saver:main',
            'map_saver_cli = nav2_map_server.map_saver_cli:main',
        ],
    },
)
