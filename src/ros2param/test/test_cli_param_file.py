"""The parameters tutorial on turtlesim and teleop: list, node info, dump, load, delete, and a
dumped file given back to turtlesim with --params-file."""

import os
import pty
import subprocess

import pytest

from ws_testing import TestNode, check, executable, ros2, ros2_side_by_side

QOS = [f'qos_overrides./parameter_events.publisher.{name}'
       for name in ('depth', 'durability', 'history', 'reliability')]
PARAM_SERVICES = ['describe_parameters', 'get_parameter_types', 'get_parameters',
                  'get_type_description', 'list_parameters', 'set_parameters',
                  'set_parameters_atomically']
PARAM_SERVICE_TYPES = ['rcl_interfaces/srv/DescribeParameters',
                       'rcl_interfaces/srv/GetParameterTypes', 'rcl_interfaces/srv/GetParameters',
                       'type_description_interfaces/srv/GetTypeDescription',
                       'rcl_interfaces/srv/ListParameters', 'rcl_interfaces/srv/SetParameters',
                       'rcl_interfaces/srv/SetParametersAtomically']


def dumped(background_r: int) -> str:
    return (
        '/turtlesim:\n'
        '  ros__parameters:\n'
        '    background_b: 255\n'
        '    background_g: 86\n'
        f'    background_r: {background_r}\n'
        '    holonomic: false\n'
        '    qos_overrides:\n'
        '      /parameter_events:\n'
        '        publisher:\n'
        '          depth: 1000\n'
        '          durability: volatile\n'
        '          history: keep_last\n'
        '          reliability: reliable\n'
        '    start_type_description_service: true\n'
        '    use_sim_time: false\n'
        '\n')


@pytest.fixture(scope='module')
def turtlesim(module_turtlesim):
    return module_turtlesim


@pytest.fixture(scope='module')
def teleop(module_ros_env, tmp_path_factory):
    """turtle_teleop_key on a pseudo-terminal, as a user starts it."""
    controller, terminal = pty.openpty()
    log_path = tmp_path_factory.mktemp('teleop') / 'teleop.log'
    log = open(log_path, 'wb')
    process = subprocess.Popen([executable('turtlesim', 'turtle_teleop_key')],
                               env=module_ros_env, stdin=terminal, stdout=log,
                               stderr=subprocess.STDOUT, start_new_session=True)
    # Ready once another participant sees its parameter services (a node only just started
    # may be missing from a fresh `ros2` process's first look at the graph).
    probe = TestNode(int(module_ros_env['ROS_DOMAIN_ID']))
    try:
        probe.spin_until(lambda: process.poll() is not None or any(
            name == '/teleop_turtle/list_parameters'
            for name, _ in probe.node.get_service_names_and_types()), 20,
            'the teleop_turtle node')
    finally:
        probe.close()
    assert process.poll() is None, log_path.read_text()
    yield process
    os.write(controller, b'q')  # its own way out: restores the terminal and exits
    try:
        process.wait(timeout=5)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()
    os.close(controller)
    os.close(terminal)
    log.close()


def lines(*items):
    return ''.join(f'{item}\n' for item in items)



def test_param_list_matches_rclcpp_nodes(module_ros_env, turtlesim, teleop):
    # Node by node: `ros2 param list` alone lists what a fresh process has discovered, which
    # without a daemon is now and then not every node yet (docs/cli.md).
    check(ros2(module_ros_env, 'param', 'list', '/teleop_turtle'), lines(
        *(f'  {name}' for name in [*QOS, 'scale_angular', 'scale_linear',
                                   'start_type_description_service', 'use_sim_time'])))
    check(ros2(module_ros_env, 'param', 'list', '/turtlesim'), lines(
        *(f'  {name}' for name in [
            'background_b', 'background_g', 'background_r', 'holonomic', *QOS,
            'start_type_description_service', 'use_sim_time'])))


def test_node_info_teleop_is_the_tutorials(module_ros_env, turtlesim, teleop):
    check(ros2(module_ros_env, 'node', 'info', '/teleop_turtle'), lines(
        '/teleop_turtle',
        '  Subscribers:',
        '    /parameter_events: rcl_interfaces/msg/ParameterEvent',
        '  Publishers:',
        '    /parameter_events: rcl_interfaces/msg/ParameterEvent',
        '    /rosout: rcl_interfaces/msg/Log',
        '    /turtle1/cmd_vel: geometry_msgs/msg/Twist',
        '  Service Servers:',
        *(f'    /teleop_turtle/{name}: {kind}'
          for name, kind in zip(PARAM_SERVICES, PARAM_SERVICE_TYPES, strict=True)),
        '  Service Clients:', '',
        '  Action Servers:', '',
        '  Action Clients:',
        '    /turtle1/rotate_absolute: turtlesim/action/RotateAbsolute'))


def test_qos_override_parameters_are_read_only(module_ros_env, turtlesim):
    check(ros2(module_ros_env, 'param', 'get', '/turtlesim', QOS[0]), 'Integer value is: 1000\n')
    check(ros2(module_ros_env, 'param', 'set', '/turtlesim', QOS[0], '5'), '',
          f"Setting parameter failed: parameter '{QOS[0]}' cannot be set because it is "
          'read-only\n')


def test_dump_load_and_params_file_round_trip(module_ros_env, turtlesim, tmp_path, launch,
                                              ros_env):
    env = module_ros_env
    check(ros2(env, 'param', 'set', '/turtlesim', 'background_r', '150'),
          'Set parameter successful\n')
    dump = ros2(env, 'param', 'dump', '/turtlesim')
    check(dump, dumped(150))
    saved = tmp_path / 'turtlesim.yaml'
    saved.write_text(dump.stdout)

    check(ros2(env, 'param', 'set', '/turtlesim', 'background_r', '10'),
          'Set parameter successful\n')
    loaded = ros2(env, 'param', 'load', '/turtlesim', str(saved))
    # As Jazzy: successes on stdout, refusals (read-only parameters) on stderr.
    check(loaded, lines(
        *(f'Set parameter {name} successful' for name in
          ('background_b', 'background_g', 'background_r', 'holonomic', 'use_sim_time'))),
        lines(*(f"Set parameter {name} failed: parameter '{name}' cannot be set because it is "
                'read-only' for name in (*QOS, 'start_type_description_service'))))
    check(ros2(env, 'param', 'get', '/turtlesim', 'background_r'), 'Integer value is: 150\n')

    # A new turtlesim (its own domain) started from the dumped file has the saved values.
    fresh = launch(argv=['ros2', 'run', 'turtlesim', 'turtlesim_node', '--headless',
                         '--ros-args', '--params-file', str(saved)])
    fresh.wait_for_output(r'Spawning turtle \[turtle1\]')
    # Humble's --output-dir, kept for older instructions: the same YAML in <dir>/<node>.yaml.
    out = tmp_path / 'out'
    out.mkdir()
    check(ros2(ros_env, 'param', 'dump', '/turtlesim', '--output-dir', str(out)),
          f"Saving to:  {out / 'turtlesim.yaml'}\n")
    assert (out / 'turtlesim.yaml').read_text() == dumped(150)[:-1]  # no print's blank line


def test_load_and_delete_refuse_bad_input(module_ros_env, turtlesim, tmp_path):
    env = module_ros_env
    check(ros2(env, 'param', 'load', '/turtlesim', str(tmp_path / 'missing.yaml')), '',
          f"Parameter file '{tmp_path / 'missing.yaml'}': No such file or directory\n", 1)
    # The node is looked up first, as upstream.
    check(ros2(env, 'param', 'load', '--spin-time', '1', '/nobody',
               str(tmp_path / 'missing.yaml')), '', 'Node not found\n', 1)
    broken = tmp_path / 'broken.yaml'
    broken.write_text('/turtlesim: [1, 2\n')
    result = ros2(env, 'param', 'load', '/turtlesim', str(broken))
    assert (result.stdout, result.returncode) == ('', 1)
    assert result.stderr == (f"Parameter file '{broken}' is not valid YAML: expected ',' or "
                             "']', but got '<stream end>' (line 2, column 1)\n")
    plain = tmp_path / 'plain.yaml'
    plain.write_text('background_r: 3\n')
    result = ros2(env, 'param', 'load', '/turtlesim', str(plain))
    assert (result.stdout, result.returncode) == ('', 1)
    assert result.stderr.startswith(f"Parameter file '{plain}' is not a ROS parameter file")
    assert result.stderr.count('\n') == 1, result.stderr
    check(ros2(env, 'param', 'delete', '/turtlesim', 'background_g'), '',
          'Deleting parameter failed: parameter background_g: Static parameter cannot be '
              'undeclared\n')
    check(ros2(env, 'param', 'get', '/turtlesim', 'background_g'), 'Integer value is: 86\n')
    check(ros2(env, 'param', 'dump', '--spin-time', '1', '/nobody'), '', 'Node not found\n', 1)
    check(ros2(env, 'param', 'dump', '/turtlesim', '--output-dir', str(tmp_path / 'nowhere')),
          '', f"Output directory '{tmp_path / 'nowhere'}' does not exist\n", 1)


STUCK_NODE = '''
import time
import rclpy
rclpy.init()
node = rclpy.create_node('stuck')
print('created', flush=True)
time.sleep(60)  # never spins: its parameter services are listed but never answer
'''


def test_param_verbs_give_up_on_a_node_that_never_answers(ros_env, launch):
    import sys
    stuck = launch(argv=[sys.executable, '-c', STUCK_NODE])
    stuck.wait_for_output('created')
    verbs = (['list', '/stuck'], ['get', '/stuck', 'use_sim_time'], ['dump', '/stuck'])
    # Each waits out the same no-answer limit on its own: side by side, not one after another.
    results = ros2_side_by_side(ros_env, *(['param', *verb] for verb in verbs), timeout=40)
    for verb, result in zip(verbs, results, strict=True):
        assert result.returncode == 1, verb
        assert result.stderr.strip().splitlines()[-1].endswith(
            's: the node is not spinning or is busy in a callback'), (verb, result.stderr)
        assert "did not answer within 5 s" in result.stderr
