from setuptools import find_packages, setup

package_name = 'launch_testing_ros'

setup(
    name=package_name,
    version='0.26.6',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='ROS helpers for launch tests: WaitForTopics.',
    license='Apache-2.0',
)
