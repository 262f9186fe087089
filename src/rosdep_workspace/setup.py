from setuptools import find_packages, setup

package_name = 'rosdep_workspace'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        ('share/' + package_name + '/rules', ['rules/base.yaml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='rosdep from PyPI, configured offline for this pip-installed stack.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'rosdep = rosdep_workspace.main:main',
        ],
    },
)
