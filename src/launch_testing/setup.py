from setuptools import find_packages, setup

package_name = 'launch_testing'

setup(
    name=package_name,
    version='3.4.4',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='Create tests which involve launch files and multiple processes.',
    license='Apache-2.0',
    entry_points={
        'console_scripts': ['launch_test = launch_testing.launch_test:main'],
        # As upstream: pytest collects launch tests of any package once this one is installed.
        'pytest11': ['launch_testing = launch_testing.pytest.hooks'],
    },
)
