from setuptools import find_packages, setup

package_name = 'rosbag2_py'

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
    description="Jazzy's rosbag2 Python API on the mcap and rosbags libraries.",
    license='Apache-2.0',
)
