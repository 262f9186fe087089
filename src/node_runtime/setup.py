from setuptools import find_packages, setup

package_name = 'node_runtime'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/config', ['config/fastdds_announce.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='What the workspace nodes share: clean Ctrl-C spinning, quicker DDS discovery, '
                'parameter-service guards, rate-limited repeated log lines.',
    license='Apache-2.0',
)
