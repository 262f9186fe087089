"""`ros2 launch` with real ROS nodes: turtlesim's multisim, the Jazzy tutorials' launch files
(run unchanged from tests/data/launch), and Node's names, namespaces, parameters, remappings
and respawn, checked over DDS by an rclpy probe and with `ros2 node list`."""

from __future__ import annotations

import os
import re
import shutil
import signal
import sys
import textwrap
import time
from pathlib import Path

import pytest
from geometry_msgs.msg import Twist
from rcl_interfaces.srv import GetParameters
from turtlesim.msg import Pose

from support import (
    REPO,
    Background,
    TestNode,
    leased_domain,
    ros2,
    ros_environment,
    stop_daemon,
    turtle_qos,
    wait_until,
)

DATA = REPO / 'tests' / 'data' / 'launch'


def headless(ros_env: dict[str, str], prefix: Path | None = None) -> dict[str, str]:
    env = dict(ros_env)
    env.pop('DISPLAY', None)
    env.pop('WAYLAND_DISPLAY', None)
    if prefix is not None:  # a package made by the test, found through the ament index
        env['AMENT_PREFIX_PATH'] = f"{prefix}:{env['AMENT_PREFIX_PATH']}"
    return env


def tutorial_package(root: Path, name: str, launch_files: list[str],
                     executables: dict[str, str] | None = None) -> Path:
    """An installed package as colcon would lay it out: index marker, launch files, lib/."""
    index = root / 'share' / 'ament_index' / 'resource_index' / 'packages'
    index.mkdir(parents=True, exist_ok=True)
    (index / name).write_text('')
    share = root / 'share' / name / 'launch'
    share.mkdir(parents=True)
    for launch_file in launch_files:
        shutil.copy(DATA / launch_file, share / launch_file)
    for exe, source in (executables or {}).items():
        lib = root / 'lib' / name
        lib.mkdir(parents=True, exist_ok=True)
        (lib / exe).write_text(f'#!{sys.executable}\n' + (DATA / source).read_text())
        (lib / exe).chmod(0o755)
    return root


def wait_for_nodes(probe, names: set[str], run, timeout: float = 30.0) -> None:
    """Wait until the probe discovers the nodes; fail with the launch's output."""
    try:
        probe.spin_until(lambda: names <= set(probe.node.get_fully_qualified_node_names()),
                         timeout, f'nodes {sorted(names)}')
    except AssertionError as error:
        raise AssertionError(f'{error}; seen: {probe.node.get_fully_qualified_node_names()}; '
                             f'launch output:\n{run.output}') from None


def get_parameter(probe, node: str, name: str):
    response = probe.call(GetParameters, f'{node}/get_parameters',
                          GetParameters.Request(names=[name]))
    value = response.values[0]
    return {1: value.bool_value, 2: value.integer_value, 3: value.double_value,
            4: value.string_value}.get(value.type)


def wait_for_background_r(probe, node: str, run, timeout: float = 30.0) -> None:
    """Wait for the tutorials' two `ros2 param set` (120 at once, 200 after a 2 s timer).

    Both must finish cleanly (a node not found exits 1) and leave one of their values. Under
    load the first can take over 2 s to find a node that has just started; the two are then
    answered at once and set their values in either order, as with ros2cli (docs/launch.md).
    """
    # Named 'ros2-3' from YAML, 'sim background_r 120-3' from Python (upstream's naming).
    finished = re.compile(r'^\[INFO\] \[[^]\n]*-[34]\]: process has finished cleanly',
                          re.MULTILINE)
    deadline = time.monotonic() + timeout
    while len(finished.findall(run.output)) < 2:
        assert time.monotonic() < deadline, run.output
        probe.spin_for(0.2)
    assert get_parameter(probe, node, 'background_r') in (120, 200), run.output

def stop(run) -> str:
    """Ctrl-C the launch as a terminal would; it must exit 0 with every node stopped."""
    os.killpg(run.popen.pid, signal.SIGINT)
    assert run.wait(timeout=30) == 0, run.output
    return run.output


def test_multisim_starts_two_turtlesims_listed_by_ros2_node_list(launch, ros_env, probe):
    env = headless(ros_env)
    started = time.monotonic()
    run = launch(argv=['ros2', 'launch', 'turtlesim', 'multisim.launch.py'], env=env)
    wait_for_nodes(probe, {'/turtlesim1/turtlesim', '/turtlesim2/turtlesim'}, run)
    print(f'multisim: both nodes discoverable {time.monotonic() - started:.2f} s after '
          '`ros2 launch`')
    listed = ros2(env, 'node', 'list')
    assert {'/turtlesim1/turtlesim', '/turtlesim2/turtlesim'} <= set(listed.stdout.split()), \
        listed.stdout
    out = run.output
    for n in (1, 2):
        assert re.search(rf'^\[INFO\] \[turtlesim_node-{n}\]: process started with pid \[\d+\]$',
                         out, re.MULTILINE), out
        assert re.search(rf'^\[turtlesim_node-\d\] \[INFO\] \[[\d.]+\] \[turtlesim{n}\.turtlesim'
                         rf'\]: Starting turtlesim with node name /turtlesim{n}/turtlesim$',
                         out, re.MULTILINE), out
    out = stop(run)
    assert '[WARNING] [launch]: user interrupted with ctrl-c (SIGINT)' in out
    assert len(re.findall(r'^\[INFO\] \[turtlesim_node-\d\]: process has finished cleanly '
                          r'\[pid \d+\]$', out, re.MULTILINE)) == 2, out


@pytest.mark.parametrize('launch_file', ['turtlesim_mimic_launch.py',
                                         'turtlesim_mimic_launch.xml',
                                         'turtlesim_mimic_launch.yaml'])
def test_mimic_tutorial_launch_file_runs_unchanged(launch, ros_env, probe, launch_file):
    run = launch(argv=['ros2', 'launch', str(DATA / launch_file)], env=headless(ros_env))
    wait_for_nodes(probe, {'/turtlesim1/sim', '/turtlesim2/sim', '/mimic'}, run)
    # The tutorial's check: drive turtlesim1, and turtlesim2's turtle follows through mimic.
    poses = probe.collect(Pose, '/turtlesim2/turtle1/pose', turtle_qos())
    publisher = probe.node.create_publisher(Twist, '/turtlesim1/turtle1/cmd_vel', 10)
    twist = Twist()
    twist.linear.x, twist.angular.z = 2.0, 1.8
    deadline = time.monotonic() + 20
    while not (poses and abs(poses[-1].x - 5.544445) > 0.2):
        assert time.monotonic() < deadline, f'turtlesim2 never moved; {poses[-1:]}'
        publisher.publish(twist)
        probe.spin_for(0.1)
    out = stop(run)
    assert re.search(r'^\[INFO\] \[mimic-3\]: process started with pid \[\d+\]$', out,
                     re.MULTILINE), out
    assert 'Traceback' not in out


def start_substitutions(launch, ros_env, directory: Path, kind: str):
    """The tutorial's package (its `kind` files) installed under `directory`, its
    `--show-args` transcript checked, and example_main_launch started."""
    prefix = tutorial_package(directory / 'install', 'launch_tutorial',
                              [f'example_main_launch.{kind}',
                               f'example_substitutions_launch.{kind}'])
    env = headless(ros_env, prefix)
    shown = ros2(env, 'launch', 'launch_tutorial', f'example_substitutions_launch.{kind}',
                 '--show-args')
    assert shown.stdout == (  # the transcript the tutorial shows
        "Arguments (pass arguments as '<name>:=<value>'):\n"
        "\n    'turtlesim_ns':\n        no description given\n        (default: 'turtlesim1')\n"
        "\n    'use_provided_red':\n        no description given\n        (default: 'False')\n"
        "\n    'new_background_r':\n        no description given\n        (default: '200')\n"
    ), shown.stdout + shown.stderr
    return launch(argv=['ros2', 'launch', 'launch_tutorial', f'example_main_launch.{kind}'],
                  env=env)


def check_substitutions(run, probe, spawn_x: float) -> None:
    wait_for_nodes(probe, {'/turtlesim2/sim'}, run)
    poses = probe.collect(Pose, '/turtlesim2/turtle2/pose', turtle_qos())
    with Background(probe):
        wait_until(lambda: bool(poses), 30, 'the turtle spawned by `ros2 service call`')
    assert abs(poses[-1].x - spawn_x) < 0.01 and abs(poses[-1].y - 2.0) < 0.01, poses[-1]
    wait_for_background_r(probe, '/turtlesim2/sim', run)
    out = stop(run)
    assert 'Traceback' not in out


def test_substitutions_tutorial_runs_unchanged(launch, ros_env, probe, tmp_path):
    # The Python files (spawn at x = 2) and the YAML ones (x = 5) side by side, YAML in a
    # domain of its own: the two runs overlap their start-up and the tutorial's 2 s timer.
    with leased_domain() as other:
        other_env = ros_environment(other)
        other_probe = TestNode(other)
        runs = []
        try:
            runs.append(start_substitutions(launch, ros_env, tmp_path / 'py', 'py'))
            runs.append(start_substitutions(launch, other_env, tmp_path / 'yaml', 'yaml'))
            check_substitutions(runs[0], probe, 2.0)
            check_substitutions(runs[1], other_probe, 5.0)
        finally:
            for run in runs:
                run.stop()  # within the lease of its domain
            other_probe.close()
            stop_daemon(other_env)  # if the tutorial's `ros2 param set` started one


def test_parameters_tutorial_launch_file_runs_unchanged(launch, ros_env, tmp_path):
    prefix = tutorial_package(tmp_path / 'install', 'python_parameters',
                              ['python_parameters_launch.py'],
                              {'minimal_param_node': 'python_parameters_node.py'})
    run = launch(argv=['ros2', 'launch', 'python_parameters', 'python_parameters_launch.py'],
                 env=headless(ros_env, prefix))
    run.wait_for_output(r'^\[minimal_param_node-1\] \[INFO\] \[[\d.]+\] '
                        r'\[custom_minimal_param_node\]: Hello earth!$', timeout=30)
    stop(run)


def test_node_namespaces_parameters_remaps_and_respawn(launch, ros_env, probe, tmp_path):
    params = tmp_path / 'colours.yaml'
    params.write_text('/**:\n  ros__parameters:\n    background_b: 30\n')
    launch_file = tmp_path / 'nodes.launch.py'
    launch_file.write_text(textwrap.dedent(f'''
        from launch import LaunchDescription
        from launch.actions import GroupAction
        from launch_ros.actions import Node, PushRosNamespace, SetParameter, SetRemap

        def generate_launch_description():
            return LaunchDescription([
                GroupAction([
                    PushRosNamespace('outer'),
                    SetParameter(name='background_g', value=50),
                    SetRemap(src='turtle1/cmd_vel', dst='drive'),
                    Node(package='turtlesim', executable='turtlesim_node', name='sim',
                         namespace='inner', parameters=[{str(params)!r}, {{'background_r': 10}}],
                         remappings=[('turtle1/pose', 'pose_out')]),
                ]),
                Node(package='turtlesim', executable='turtlesim_node', name='plain',
                     respawn=True, respawn_delay=0.5),
            ])
        '''))
    run = launch(argv=['ros2', 'launch', str(launch_file)], env=headless(ros_env))
    wait_for_nodes(probe, {'/outer/inner/sim', '/plain'}, run)
    assert get_parameter(probe, '/outer/inner/sim', 'background_r') == 10
    assert get_parameter(probe, '/outer/inner/sim', 'background_g') == 50
    assert get_parameter(probe, '/outer/inner/sim', 'background_b') == 30
    assert get_parameter(probe, '/plain', 'background_g') == 86  # outside the group's scope
    topics = dict(probe.node.get_topic_names_and_types())
    assert '/outer/inner/pose_out' in topics and '/outer/inner/drive' in topics, topics
    assert '/outer/inner/turtle1/pose' not in topics, topics
    plain_pid = int(re.search(r'^\[INFO\] \[turtlesim_node-2\]: process started with pid '
                              r'\[(\d+)\]$', run.output, re.MULTILINE).group(1))
    os.kill(plain_pid, signal.SIGKILL)
    run.wait_for_output(rf"^\[ERROR\] \[turtlesim_node-2\]: process has died \[pid {plain_pid}, "
                        r"exit code -9, cmd '\S+/lib/turtlesim/turtlesim_node --ros-args -r "
                        r"__node:=plain'\]\.$", timeout=10)
    run.wait_for_output(r'^\[INFO\] \[turtlesim_node-2\]: process started with pid '
                        rf'\[(?!{plain_pid}\])\d+\]$', timeout=10)
    stop(run)


def test_event_handlers_tutorial_runs_unchanged(launch, ros_env, probe, tmp_path):
    prefix = tutorial_package(tmp_path / 'install', 'launch_tutorial',
                              ['example_event_handlers_launch.py'])
    env = headless(ros_env, prefix)
    env['USER'] = 'learner'
    # As after the earlier tutorial pages, the ros2 daemon runs already. A cold one answers
    # its first query only after ~4 s of discovery, and then the tutorial's two `ros2 param
    # set` (2 s apart) can finish in either order (docs/launch.md).
    ros2(env, 'daemon', 'start')
    ros2(env, 'node', 'list')
    run = launch(argv=['ros2', 'launch', 'launch_tutorial', 'example_event_handlers_launch.py',
                       'turtlesim_ns:=turtlesim3', 'use_provided_red:=True',
                       'new_background_r:=200'], env=env)
    run.wait_for_output(r'^\[INFO\] \[launch\.user\]: Spawn request says "requester: making '
                        r'request: turtlesim\.srv\.Spawn_Request\(x=2\.0, y=2\.0, theta=0\.2',
                        timeout=30)
    run.wait_for_output(r'^\[INFO\] \[launch\.user\]: Spawn finished$', timeout=30)
    wait_for_nodes(probe, {'/turtlesim3/sim'}, run)
    wait_for_background_r(probe, '/turtlesim3/sim', run)
    # Closing the window ends turtlesim: the launch logs it and shuts itself down.
    pid = int(re.search(r'^\[INFO\] \[turtlesim_node-1\]: process started with pid \[(\d+)\]',
                        run.output, re.MULTILINE).group(1))
    os.kill(pid, signal.SIGINT)
    assert run.wait(timeout=30) == 0, run.output
    lines = run.output.splitlines()
    assert '[INFO] [launch.user]: Turtlesim started, spawning turtle' in lines
    assert '[INFO] [launch.user]: learner closed the turtlesim window' in lines
    assert '[INFO] [launch.user]: Launch was asked to shutdown: Window closed' in lines
