from setuptools import find_packages, setup

package_name = 'nav2_controller'

setup(
    name=package_name,
    version='1.3.13',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml', 'README.md']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description="Nav2's controller_server in Python, with its local costmap in the same process.",
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'controller_server = nav2_controller.controller_server:main',
        ],
    },
)
