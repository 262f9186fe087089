from setuptools import setup

package_name = 'tf2_ros_py'

# No module of its own: `import tf2_ros` comes from the tf2_ros package (see package.xml).
setup(
    name=package_name,
    version='0.36.4',
    packages=[],
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=True,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='Upstream name of the Python tf2_ros package; here it depends on tf2_ros.',
    license='BSD-3-Clause',
)
