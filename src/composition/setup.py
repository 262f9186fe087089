from setuptools import find_packages, setup

package_name = 'composition'

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
    description='Stand-in for the composition demo: several nodes in one process.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'manual_composition = composition.manual_composition:main',
        ],
    },
)
