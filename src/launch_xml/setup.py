from setuptools import find_packages, setup

package_name = 'launch_xml'

setup(
    name=package_name,
    version='0.1.0',
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
    description='XML front end for launch: reads launch files into launch.frontend entities.',
    license='Apache-2.0',
    entry_points={
        'launch.frontend.parser': [
            'xml = launch_xml:Parser',
        ],
    },
)
