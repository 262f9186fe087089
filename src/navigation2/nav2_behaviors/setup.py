from setuptools import find_packages, setup

package_name = 'nav2_behaviors'

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
    description="Nav2's behavior_server in Python: spin, backup, drive_on_heading, wait, "
                'assisted_teleop.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'behavior_server = nav2_behaviors.behavior_server:main',
        ],
    },
)
