from setuptools import find_packages, setup

package_name = 'nav2_util'

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
    description="What Nav2's Python servers share: nav2_util's LifecycleNode and "
                'LifecycleServiceClient, checked parameter declarations.',
    license='Apache-2.0',
)
