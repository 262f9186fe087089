from setuptools import find_packages, setup

package_name = 'nav2_waypoint_follower'

setup(
    name=package_name,
    version='1.3.13',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description="Nav2's waypoint_follower in Python: follow_waypoints over navigate_to_pose.",
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'waypoint_follower = nav2_waypoint_follower.waypoint_follower:main',
        ],
    },
)
