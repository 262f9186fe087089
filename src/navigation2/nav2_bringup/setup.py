from glob import glob

from setuptools import find_packages, setup

package_name = 'nav2_bringup'

setup(
    name=package_name,
    version='1.3.13',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch', glob('launch/*.py')),
        ('share/' + package_name + '/params', glob('params/*.yaml')),
        ('share/' + package_name + '/rviz', glob('rviz/*.rviz')),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description="Nav2's bringup: launch files, params, and the nav2_container.",
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'nav2_container = nav2_bringup.container:main',
        ],
    },
)
