from setuptools import find_packages, setup

package_name = 'tf2_py'

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
    description="tf2's BufferCore in pure Python, with upstream's API and messages.",
    license='BSD-3-Clause',
)
