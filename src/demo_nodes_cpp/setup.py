from setuptools import find_packages, setup

package_name = 'demo_nodes_cpp'

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
    description="Stand-in for demo_nodes_cpp's parameter_blackboard.",
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'parameter_blackboard = demo_nodes_cpp.parameter_blackboard:main',
        ],
    },
)
