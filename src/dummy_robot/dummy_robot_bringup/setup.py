from glob import glob

from setuptools import setup

package_name = 'dummy_robot_bringup'

setup(
    name=package_name,
    version='0.33.5',
    packages=[],
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch', glob('launch/*_launch.*') + glob('launch/*.urdf')),
        ('share/' + package_name + '/config', glob('config/*')),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description="Stand-in for upstream's dummy_robot_bringup.",
    license='Apache-2.0',
)
