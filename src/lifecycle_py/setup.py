from glob import glob

from setuptools import find_packages, setup

package_name = 'lifecycle_py'

setup(
    name=package_name,
    version='0.33.5',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/launch', glob('launch/*.py')),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description="Stand-in for upstream's lifecycle_py demo: lifecycle_talker on rclpy.lifecycle.",
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'lifecycle_talker = lifecycle_py.talker:main',
        ],
    },
)
