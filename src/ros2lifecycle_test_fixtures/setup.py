from setuptools import find_packages, setup

package_name = 'ros2lifecycle_test_fixtures'

setup(
    name=package_name,
    version='0.32.1',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description="Stand-in for upstream's ros2lifecycle test fixture, in Python on rclpy.lifecycle.",
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'simple_lifecycle_node = ros2lifecycle_test_fixtures.simple_lifecycle_node:main',
        ],
    },
)
