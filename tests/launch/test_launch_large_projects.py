""""Using ROS 2 launch for large projects" (Jazzy), typed as the page says: a package made by
`ros2 pkg create`, the page's launch files and turtlesim.yaml, its setup.py data_files, built
with colcon, then `ros2 launch launch_tutorial launch_turtlesim_launch.py`.

What the page shows: three turtlesim worlds (the first with launch-argument backgrounds,
/turtlesim2/sim namespaced by PushROSNamespace in a GroupAction, /turtlesim3/sim; both take
the `/**` wildcard parameters), turtle2 spawned and chasing carrot1 (the included launch
file's target_frame overridden by the top-level one), mimic remapped so that
turtlesim2's turtle1 copies turtle2, the fixed-frame broadcaster named from $USER, RViz.
"""
from __future__ import annotations

import math
import shutil
from pathlib import Path

import pytest
from turtlesim.msg import Pose

from support import ros2, turtle_qos
from ws_testing import colcon_workspace

SPAWN = 5.544445  # turtlesim's first turtle starts in the middle
PAGE_FILES = Path(__file__).parents[1] / 'data' / 'launch_tutorial'
DATA_FILES = '''\
        (os.path.join('share', package_name, 'launch'),
            glob(os.path.join('launch', '*launch.[pxy][yma]*'))),
        (os.path.join('share', package_name, 'config'),
            glob(os.path.join('config', '*.yaml'))),
        (os.path.join('share', package_name, 'rviz'),
            glob(os.path.join('config', '*.rviz'))),
'''


@pytest.fixture(scope='module')
def workspace(tmp_path_factory) -> Path:
    with colcon_workspace(tmp_path_factory, 'large_ws') as ws:
        package = ws.create('launch_tutorial', '--build-type', 'ament_python', '--license',
                            'Apache-2.0')
        (package / 'launch').mkdir()
        (package / 'config').mkdir()
        for page_file in PAGE_FILES.glob('*launch.py'):
            shutil.copy(page_file, package / 'launch')
        shutil.copy(PAGE_FILES / 'turtlesim.yaml', package / 'config')
        setup = (package / 'setup.py').read_text()
        setup = 'import os\nfrom glob import glob\n' + setup.replace(
            "        ('share/' + package_name, ['package.xml']),\n",
            "        ('share/' + package_name, ['package.xml']),\n" + DATA_FILES)
        (package / 'setup.py').write_text(setup)
        ws.build('--symlink-install', timeout=240)
    return ws.root


def test_the_pages_top_level_launch_file(workspace, launch, ros_env, probe) -> None:
    env = {**ros_env, 'USER': 'learner'}
    demo = launch(argv=['bash', '-c', f'source {workspace}/install/setup.bash && '
                        'exec ros2 launch launch_tutorial launch_turtlesim_launch.py'], env=env)
    demo.wait_for_output(r'\[listener\]: Successfully spawned turtle2', timeout=60)
    nodes = {f'{ns.rstrip("/")}/{name}' for name, ns in probe.node.get_node_names_and_namespaces()}
    for expected in ('/sim', '/turtlesim2/sim', '/turtlesim3/sim', '/broadcaster1',
                     '/broadcaster2', '/listener', '/mimic', '/learner_fixed_broadcaster'):
        probe.spin_until(lambda name=expected: name in {
            f'{ns.rstrip("/")}/{n}' for n, ns in probe.node.get_node_names_and_namespaces()},
            20, f'node {expected}')
    assert nodes  # the graph was read
    for node, rgb in (('/sim', (0, 84, 122)), ('/turtlesim2/sim', (150, 86, 255)),
                      ('/turtlesim3/sim', (150, 86, 255))):
        for channel, value in zip('rgb', rgb, strict=True):
            answer = ros2(env, 'param', 'get', node, f'background_{channel}')
            assert answer.stdout == f'Integer value is: {value}\n', (node, answer)

    poses: dict[str, Pose] = {}
    for topic in ('/turtle1/pose', '/turtle2/pose', '/turtlesim2/turtle1/pose'):
        probe.node.create_subscription(Pose, topic, lambda msg, t=topic: poses.__setitem__(t, msg),
                                       turtle_qos())
    probe.spin_until(lambda: len(poses) == 3, 20, 'the three turtles\' poses')
    # turtle2 drives to carrot1, 2 m along turtle1's y axis (turtle1 stands at its start).
    turtle1 = poses['/turtle1/pose']
    carrot = (turtle1.x - 2.0 * math.sin(turtle1.theta), turtle1.y + 2.0 * math.cos(turtle1.theta))
    probe.spin_until(lambda: math.dist((poses['/turtle2/pose'].x, poses['/turtle2/pose'].y),
                                       carrot) < 1.0, 30, 'turtle2 reaching carrot1')
    # mimic: turtlesim2's turtle1 (spawned in the middle) drove off as turtle2 did.
    moved = poses['/turtlesim2/turtle1/pose']
    assert math.dist((moved.x, moved.y), (SPAWN, SPAWN)) > 1.0, moved
    # rviz2 (no output='screen') says where its page is through the logger, which is shown.
    demo.wait_for_output(r'^\[rviz2-\d+\] \[INFO\] \[\d+\.\d+\] \[rviz2\]: RViz: '
                         r'http://127\.0\.0\.1:\d+/rviz\?token=\w+&config=\S+turtle_rviz\.rviz')
    assert demo.stop() == 0
    assert 'Traceback' not in demo.output
