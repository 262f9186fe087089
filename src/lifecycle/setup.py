from glob import glob

from setuptools import find_packages, setup

package_name = 'lifecycle'

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
    extras_require={'test': ['pytest']},  # colcon test runs test/ with pytest
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description="Stand-in for upstream's lifecycle demo, in Python on rclpy.lifecycle.",
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'lifecycle_talker = lifecycle.lifecycle_talker:main',
            'lifecycle_listener = lifecycle.lifecycle_listener:main',
            'lifecycle_service_client = lifecycle.lifecycle_service_client:main',
        ],
    },
)
