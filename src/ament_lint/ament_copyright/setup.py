from setuptools import find_packages, setup

package_name = 'ament_copyright'

setup(
    name=package_name,
    version='0.17.3',
    packages=find_packages(exclude=['test']),
    package_data={package_name: ['licenses/*.txt']},
    data_files=[
        ('share/ament_index/resource_index/packages', ['resource/' + package_name]),
        ('share/' + package_name, ['package.xml']),
    ],
    install_requires=['setuptools'],
    zip_safe=False,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='Check source files for copyright and license headers.',
    license='Apache-2.0',
    entry_points={
        # On PATH (bin/), where ament_cmake_copyright's find_program looks.
        'console_scripts': [
            'ament_copyright = ament_copyright.main:main',
            'ament_lint_cmake = ament_copyright.lint_cmake:main',
            'ament_xmllint = ament_copyright.xmllint:main',
            'ament_lint_skip = ament_copyright.skip:main',
        ],
        'pytest11': [
            'ament_copyright = ament_copyright.pytest_marker',
        ],
    },
)
