from setuptools import find_packages, setup

package_name = 'image_tools'

setup(
    name=package_name,
    version='0.33.5',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description="Stand-in for upstream's image_tools (C++ and OpenCV upstream), in Python.",
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'cam2image = image_tools.cam2image:main',
            'showimage = image_tools.showimage:main',
        ],
    },
)
