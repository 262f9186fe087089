from setuptools import find_packages, setup

package_name = 'nav2_lifecycle_manager'

setup(
    name=package_name,
    version='1.3.13',
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
    description="Nav2's lifecycle manager in Python: brings managed nodes up and down in order.",
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'lifecycle_manager = nav2_lifecycle_manager.lifecycle_manager:main',
        ],
    },
)
