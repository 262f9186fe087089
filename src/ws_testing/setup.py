from setuptools import find_packages, setup

package_name = 'ws_testing'

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools', 'pytest'],
    extras_require={'test': ['pytest']},  # colcon test runs test/ with pytest
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description="The workspace's test fixtures as a pytest plugin.",
    license='Apache-2.0',
    entry_points={
        # Loaded by every pytest run where the package is installed, as launch_testing's
        # plugin: fixtures only; the leak check and the rest are switched on by the ini option
        # ws_testing_checks (the workspace's pyproject.toml), see ws_testing/plugin.py.
        'pytest11': ['ws_testing = ws_testing.plugin'],
    },
)
