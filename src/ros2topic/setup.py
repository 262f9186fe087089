from setuptools import find_packages, setup

package_name = 'ros2topic'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description="Upstream's ros2topic.api on the ros2cli_lite `ros2 topic` verbs.",
    license='Apache-2.0',
)
