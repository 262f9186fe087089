from pathlib import Path

from setuptools import find_packages, setup

package_name = 'rqt_web'
# The upstream rqt package names the tutorials type (`ros2 run rqt_graph rqt_graph`): this
# package registers each in the ament index and installs its lib/<name>/<name> launcher.
TOOLS = ['rqt_gui', 'rqt_graph', 'rqt_console', 'rqt_service_caller', 'rqt_reconfigure',
         'rqt_topic', 'rqt_action', 'rqt_tf_tree', 'rviz2']
# The pages' files, each folder of static/ (the RViz page's ES modules are static/rviz/ and
# its subfolders) installed as it is in the package.
STATIC_FILES = {d: sorted(str(f) for f in Path(package_name, d).iterdir() if f.is_file())
                for d in sorted({str(p.parent.relative_to(package_name))
                                 for p in Path(package_name, 'static').rglob('*') if p.is_file()})}

setup(
    name=package_name,
    version='0.1.0',
    packages=find_packages(exclude=['test']),
    package_data={package_name: [d + '/*' for d in STATIC_FILES]},
    data_files=[
        ('share/ament_index/resource_index/packages',
         ['resource/' + package_name] + ['resource/' + tool for tool in TOOLS]),
        ('share/' + package_name, ['package.xml', 'package.json', 'package-lock.json']),
        *[('share/' + package_name + '/' + d, files) for d, files in STATIC_FILES.items()],
        *[('lib/' + tool, ['scripts/' + tool]) for tool in TOOLS],
    ],
    install_requires=['setuptools'],
    extras_require={'test': ['pytest']},  # colcon test runs test/ with pytest
    zip_safe=False,
    maintainer='Turtlesim Team',
    maintainer_email='team@turtles.example.com',
    description='rqt in the browser (graph, services, topics, parameters, console, actions, '
                'turtlesim view).',
    license='Apache-2.0',
    entry_points={
        'console_scripts': [
            'rqt = rqt_web.launcher:main',
            'rqt_graph = rqt_web.launcher:graph_main',
            'rqt_console = rqt_web.launcher:console_main',
            'rviz2 = rqt_web.rviz_launcher:main',
        ],
        # A headless turtlesim prints where to watch it (turtlesim_py/canvas_stream.py).
        'turtlesim.live_view': [
            'rqt_web = rqt_web.instance:turtlesim_live_view',
        ],
    },
)
