from setuptools import find_packages, setup

package_name = 'dummy_map_server'

setup(
    name=package_name,
    version='0.33.5',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description="Stand-in for upstream's dummy_map_server (C++ upstream), in Python.",
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'dummy_map_server = dummy_map_server.dummy_map_server:main',
        ],
    },
)
