from setuptools import find_packages, setup

package_name = 'tf2_tools'

setup(
    name=package_name,
    version='0.36.4',
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
    description='view_frames: draw the tf frame tree (Graphviz) as Jazzy tf2_tools does.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'view_frames = tf2_tools.view_frames:main',
        ],
    },
)
