from glob import glob

from setuptools import find_packages, setup

package_name = 'nav2_bt_navigator'

setup(
    name=package_name,
    version='1.3.13',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/behavior_trees', glob('behavior_trees/*.xml')),
    ],
    install_requires=['setuptools'],
    extras_require={'test': ['pytest']},  # colcon test runs test/ with pytest
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description="Nav2's bt_navigator in Python: navigate_to_pose and navigate_through_poses "
                'served by behavior trees.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'bt_navigator = nav2_bt_navigator.bt_navigator:main',
        ],
    },
)
