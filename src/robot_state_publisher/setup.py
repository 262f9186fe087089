from setuptools import find_packages, setup

package_name = 'robot_state_publisher'

setup(
    name=package_name,
    version='3.3.3',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='robot_state_publisher in Python: URDF to /robot_description, /tf, /tf_static.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'robot_state_publisher = robot_state_publisher.robot_state_publisher:main',
        ],
    },
)
