from setuptools import find_packages, setup

package_name = 'joint_state_publisher_gui'

setup(
    name=package_name,
    version='2.4.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='joint_state_publisher with sliders in the rqt web app.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'joint_state_publisher_gui = joint_state_publisher_gui.joint_state_publisher_gui:main',
        ],
    },
)
