from setuptools import setup

package_name = 'nav2_simple_commander'

setup(
    name=package_name,
    version='1.3.13',
    packages=[package_name],
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description="Stand-in for upstream's nav2_simple_commander: BasicNavigator and the costmap "
                'helpers, for writing mobile robot applications in Python 3.',
    license='Apache-2.0',
)
