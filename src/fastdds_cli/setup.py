from setuptools import find_packages, setup

package_name = 'fastdds_cli'

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
    description='fastdds discovery: the Fast DDS wheel\'s discovery server as the pages type it.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'fastdds = fastdds_cli.fastdds:main',
        ],
    },
)
