from glob import glob

from setuptools import find_packages, setup

package_name = 'ros2cli'

setup(
    name=package_name,
    version='0.32.1',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
        # The commands this package adds to `ros2` (see ros2cli/cli.py): `ros2 daemon`.
        ('share/ament_index/resource_index/ros2cli.command', sorted(glob('resource/commands/*'))),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='The ros2 command (its command lookup), the ros2 daemon and the shared node and '
                'graph access of its commands.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'ros2 = ros2cli.cli:main',
        ],
    },
)
# No script_dir redirect: the `ros2` console script goes to <prefix>/bin, which the sourced
# workspace puts on PATH.
