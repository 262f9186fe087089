from setuptools import find_packages, setup

package_name = 'nav2_regulated_pure_pursuit_controller'

setup(
    name=package_name,
    version='1.3.13',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml', 'README.md']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description="Nav2's Regulated Pure Pursuit controller plugin in Python.",
    license='Apache-2.0',
    entry_points={
        # controller_server finds controllers by upstream's type name (pluginlib's role)
        'nav2_core.controllers': [
            'nav2_regulated_pure_pursuit_controller::RegulatedPurePursuitController = '
            'nav2_regulated_pure_pursuit_controller.controller:RegulatedPurePursuitController',
        ],
    },
)
