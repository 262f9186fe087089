from setuptools import find_packages, setup

package_name = 'ros2cli'

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
    description="ros2cli's node modules for third-party tools (NodeStrategy, DirectNode, "
                'DaemonNode) on ros2cli_lite.',
    license='Apache-2.0',
)
