"""Jazzy's How-to pages typed as written, checked against what the pages (and Jazzy) show:
"Passing ROS arguments to nodes via the command-line", "Using the ros2 param command-line
tool", "Using Python, XML, and YAML for ROS 2 Launch Files" and "Working with multiple RMW
implementations".

Where a page's listing differs from what Jazzy prints, Jazzy wins and a comment says so.
"""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pytest
from rcl_interfaces.srv import GetParameters
from turtlesim.msg import Pose

from support import (
    REPO,
    Terminal,
    TestNode,
    executable,
    leased_domain,
    ros2,
    ros_environment,
    stop_daemon,
    turtle_qos,
)

LAUNCH_FILES = REPO / 'tests' / 'data' / 'launch_formats'
# The page lists these without the two spaces Jazzy's `ros2 param list` indents names with,
# and without start_type_description_service, which every Jazzy node (rclcpp and rclpy) has.
BLACKBOARD_PARAMETERS = ''.join(f'  {name}\n' for name in (
    'a_string',
    'qos_overrides./parameter_events.publisher.depth',
    'qos_overrides./parameter_events.publisher.durability',
    'qos_overrides./parameter_events.publisher.history',
    'qos_overrides./parameter_events.publisher.reliability',
    'some_int',
    'some_lists.some_doubles',
    'some_lists.some_integers',
    'start_type_description_service',
    'use_sim_time'))
DEMO_PARAMS = '''\
parameter_blackboard:
    ros__parameters:
        some_int: 42
        a_string: "Hello world"
        some_lists:
            some_integers: [1, 2, 3, 4]
            some_doubles : [3.14, 2.718]
'''


def lines(env: dict[str, str], *args: str) -> set[str]:
    done = ros2(env, *args)
    assert done.returncode == 0, done
    return set(done.stdout.splitlines())


def check(env: dict[str, str], args: str, expected: str, stderr: str = '') -> None:
    """`ros2 ARGS` (split like a shell, quotes kept) prints `expected` on stdout, `stderr` on
    stderr, and exits 0 (ros2param's refusals too)."""
    import shlex
    done = ros2(env, *shlex.split(args))
    assert (done.returncode, done.stdout, done.stderr) == (0, expected, stderr), (args, done)


def in_directory(directory: Path, command: str) -> list[str]:
    return ['bash', '-c', f'cd {directory} && exec {command}']


def test_node_arguments_page(launch, ros_env, tmp_path) -> None:
    talker = launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'talker', '--ros-args', '-r',
                          '__ns:=/demo', '-r', '__node:=my_talker', '-r', 'chatter:=my_topic'])
    composed = launch(argv=['ros2', 'run', 'composition', 'manual_composition', '--ros-args',
                            '-r', 'talker:__node:=my_talker', '-r', 'listener:__node:=my_listener'])
    blackboard = launch(argv=[
        'ros2', 'run', 'demo_nodes_cpp', 'parameter_blackboard', '--ros-args', '-p',
        'some_int:=42', '-p', 'a_string:=Hello world', '-p',
        'some_lists.some_integers:=[1, 2, 3, 4]', '-p', 'some_lists.some_doubles:=[3.14, 2.718]'])
    talker.wait_for_output(r"^\[INFO\] \[\d+\.\d+\] \[demo\.my_talker\]: "
                           r"Publishing: 'Hello World: 1'$", timeout=20)
    composed.wait_for_output(r'^\[INFO\] \[\d+\.\d+\] \[my_listener\]: '
                             r'I heard: \[Hello World: \d+\]$', timeout=20)
    composed.wait_for_output(r'\[Client\]: Got result: \[5\]$')
    assert re.search(r'\[Server\]: Incoming request: \[a: 2, b: 3\]$', composed.output, re.M)
    assert {'/demo/my_talker', '/my_talker', '/my_listener', '/Server', '/Client',
            '/parameter_blackboard'} <= lines(ros_env, 'node', 'list')
    assert {'/demo/my_topic', '/chatter'} <= lines(ros_env, 'topic', 'list')
    check(ros_env, 'param list parameter_blackboard', BLACKBOARD_PARAMETERS)
    check(ros_env, 'param get parameter_blackboard a_string', 'String value is: Hello world\n')
    composed.stop()
    blackboard.stop()

    # The node and its topic renamed, each remap rule for one node of the process.
    composed = launch(argv=[
        'ros2', 'run', 'composition', 'manual_composition', '--ros-args', '-r',
        'talker:__node:=my_talker', '-r', 'my_talker:chatter:=my_topic', '-r',
        'listener:__node:=my_listener', '-r', 'my_listener:chatter:=my_topic'])
    (tmp_path / 'demo_params.yaml').write_text(DEMO_PARAMS)
    blackboard = launch(argv=in_directory(
        tmp_path, 'ros2 run demo_nodes_cpp parameter_blackboard --ros-args '
        '--params-file demo_params.yaml'))
    composed.wait_for_output(r'\[my_listener\]: I heard: \[Hello World: \d+\]$', timeout=20)
    info = ros2(ros_env, 'node', 'info', '/my_listener').stdout
    assert '  Subscribers:\n    /my_topic: std_msgs/msg/String\n' in info, info
    blackboard.wait_for_output(r'.')  # up (it logs nothing otherwise)
    check(ros_env, 'param list parameter_blackboard', BLACKBOARD_PARAMETERS)
    check(ros_env, 'param get parameter_blackboard some_int', 'Integer value is: 42\n')


def test_ros2_param_page(launch, ros_env, tmp_path) -> None:
    # The page's /my_node: a string my_string and an integer-array my_int_array.
    launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'parameter_blackboard', '--ros-args', '-r',
                 '__node:=my_node', '-p', 'my_string:=hello', '-p', 'my_int_array:=[1, 2, 3]'])
    names = ''.join(f'  {name}\n' for name in (
        'my_int_array', 'my_string', 'qos_overrides./parameter_events.publisher.depth',
        'qos_overrides./parameter_events.publisher.durability',
        'qos_overrides./parameter_events.publisher.history',
        'qos_overrides./parameter_events.publisher.reliability',
        'start_type_description_service', 'use_sim_time'))
    check(ros_env, 'param list /my_node', names)
    check(ros_env, 'param list', '/my_node:\n' + names)
    check(ros_env, 'param get /my_node use_sim_time', 'Boolean value is: False\n')
    check(ros_env, 'param set /my_node use_sim_time false', 'Set parameter successful\n')
    # "will not work": YAML reads off as a boolean.
    check(ros_env, 'param set /my_node my_string off', '',
          'Setting parameter failed: Wrong parameter type, parameter {my_string} is of type '
          '{string}, setting it to {bool} is not allowed.\n')
    # The page types `ros param set` here (sic): ros2 is meant.
    check(ros_env, "param set /my_node my_string '!!str off'", 'Set parameter successful\n')
    check(ros_env, 'param get /my_node my_string', 'String value is: off\n')
    check(ros_env, "param set /my_node my_int_array '[foo,off,1]'", '',
          'Setting parameter failed: Wrong parameter type, parameter {my_int_array} is of type '
          '{integer_array}, setting it to {string} is not allowed.\n')
    check(ros_env, "param set /my_node my_string '[foo,off,1]'", 'Set parameter successful\n')
    check(ros_env, 'param get /my_node my_string', 'String value is: [foo,off,1]\n')
    check(ros_env, 'param describe /my_node use_sim_time',
          'Parameter name: use_sim_time\n  Type: boolean\n  Constraints:\n')
    dumped = ros2(ros_env, 'param', 'dump', '/my_node')
    assert dumped.returncode == 0, dumped
    assert dumped.stdout.startswith('/my_node:\n  ros__parameters:\n    my_int_array:\n'
                                    '    - 1\n    - 2\n    - 3\n'
                                    "    my_string: '[foo,off,1]'\n"), dumped.stdout
    (tmp_path / 'my_node.yaml').write_text(dumped.stdout)
    check(ros_env, "param set /my_node my_string 'changed'", 'Set parameter successful\n')
    loaded = ros2(ros_env, 'param', 'load', '/my_node', str(tmp_path / 'my_node.yaml'))
    assert 'Set parameter my_string successful\n' in loaded.stdout, loaded
    check(ros_env, 'param get /my_node my_string', 'String value is: [foo,off,1]\n')
    # A parameter declared from the command line is statically typed: not deletable.
    delete = ros2(ros_env, 'param', 'delete', '/my_node', 'my_string')
    assert (delete.returncode, delete.stdout) == (0, ''), delete
    assert delete.stderr.startswith('Deleting parameter failed: '), delete


def namespaced_nodes(probe: TestNode) -> set[str]:
    return {f'{ns.rstrip("/")}/{name}' for name, ns in probe.node.get_node_names_and_namespaces()}


def start_launch_file(launch, page_file: str, env: dict[str, str], directory: Path):
    shutil.copy(LAUNCH_FILES / page_file, directory)
    return launch(argv=in_directory(directory, f'ros2 launch {page_file} background_r:=255'),
                  env=env)


def check_launched(demo, page_file: str, probe: TestNode) -> None:
    """The page's nodes in their namespaces, the talkers heard, background_r from the
    command line."""
    # The Python file pushes the literal 'chatter_py_ns'; XML and YAML use the arguments.
    spaces = (['/chatter_py_ns', '/chatter_xml_ns', '/chatter_yaml_ns']
              if page_file.endswith('.py') else
              ['/chatter/py/ns', '/chatter/xml/ns', '/chatter/yaml/ns'])
    expected = {'/talker', '/listener', '/turtlesim1/sim', '/turtlesim2/sim', '/mimic'} | {
        f'{space}/{node}' for space in spaces for node in ('talker', 'listener')}
    probe.spin_until(lambda: expected <= namespaced_nodes(probe), 40,
                     f'the nodes {sorted(expected)} of {page_file}')
    # The page's own check of the includes is the listeners hearing their talkers.
    for space in spaces:
        demo.wait_for_output(rf'\[listener-\d+\] \[INFO\] \[\d+\.\d+\] '
                             rf'\[{space[1:].replace("/", ".")}\.listener\]: I heard', timeout=20)
    answer = probe.call(GetParameters, '/turtlesim2/sim/get_parameters',
                        GetParameters.Request(names=['background_r', 'background_g']))
    assert [value.integer_value for value in answer.values] == [255, 255]
    assert 'Traceback' not in demo.output


def test_launch_file_formats_page_python(launch, ros_env, probe, tmp_path) -> None:
    demo = start_launch_file(launch, 'example_launch.py', ros_env, tmp_path)
    check_launched(demo, 'example_launch.py', probe)
    # "Controlling the turtles": teleop in turtlesim1; mimic makes turtlesim2's turtle follow.
    poses: list[Pose] = []
    probe.node.create_subscription(Pose, '/turtlesim2/turtle1/pose', poses.append, turtle_qos())
    teleop = Terminal([executable('turtlesim', 'turtle_teleop_key'), '--ros-args', '--remap',
                       '__ns:=/turtlesim1'], ros_env)
    try:
        teleop.wait_for_output("'Q' to quit.")
        probe.spin_until(lambda: probe.node.count_subscribers('/turtlesim1/turtle1/cmd_vel') == 1
                         and probe.node.count_publishers('/turtlesim1/turtle1/cmd_vel') == 1
                         and poses, 15, 'teleop and turtlesim1 connected')
        probe.spin_for(0.5)  # the teleop's side of the match too (a volatile topic)
        start = poses[-1]
        teleop.press(b'\x1b[A')
        probe.spin_until(lambda: poses[-1].x > start.x + 0.5, 10,
                         "turtlesim2's turtle mimicking turtlesim1's")
        teleop.press(b'q')
        assert teleop.process.wait(timeout=10) == 0
    finally:
        teleop.close()


def test_launch_file_formats_page_xml_and_yaml(launch, ros_env, probe, tmp_path) -> None:
    # Side by side, each in its own domain: the two runs overlap their start-up waits.
    with leased_domain() as other:
        other_env = ros_environment(other)
        other_probe = TestNode(other)
        try:
            xml = start_launch_file(launch, 'example_launch.xml', ros_env, tmp_path)
            yaml = start_launch_file(launch, 'example_launch.yaml', other_env, tmp_path)
            check_launched(xml, 'example_launch.xml', probe)
            check_launched(yaml, 'example_launch.yaml', other_probe)
            assert yaml.stop() == 0
        finally:
            yaml.stop()
            other_probe.close()
            stop_daemon(other_env)


ABSENT_RMW = (r"^\[ERROR\] \[\d+\.\d+\] \[rcl\]: Expected RMW implementation identifier of "
              r"'{}' but instead found 'rmw_fastrtps_cpp', exiting with 102\.")


@pytest.mark.parametrize('rmw, command, returncode', [
    ('rmw_connextdds', 'run demo_nodes_cpp talker', 102),
    ('rmw_connextdds', 'run demo_nodes_py listener', 102),
    ('rmw_cyclonedds_cpp', 'node list --no-daemon', 102),
    # The daemon for these settings dies as it starts: its rcl line is the reason (exit 1).
    ('rmw_cyclonedds_cpp', 'node list', 1),
])
def test_multiple_rmw_page_names_an_absent_rmw(rmw, command, returncode, ros_env) -> None:
    """Only Fast DDS is installed: rcl's own check ends the process with its line and 102."""
    env = {**ros_env, 'RMW_IMPLEMENTATION': rmw}
    done = ros2(env, *command.split())
    stop_daemon(env)
    assert done.returncode == returncode, done
    assert re.search(ABSENT_RMW.format(rmw), done.stderr, re.M), done.stderr
    assert len(done.stderr.strip().splitlines()) == 1, done.stderr  # rcl's line, no traceback


def test_multiple_rmw_page_with_the_installed_rmw(launch, ros_env) -> None:
    env = {**ros_env, 'RMW_IMPLEMENTATION': 'rmw_fastrtps_cpp'}
    talker = launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'talker'], env=env)
    talker.wait_for_output(r"\[talker\]: Publishing: 'Hello World: 1'$", timeout=20)
    assert '/talker' in lines(env, 'node', 'list')  # starts the daemon with this RMW
    check(env, 'daemon stop', 'The daemon has been stopped\n')
