"""The turtlesim tutorial's `ros2` commands against the real turtlesim_node (headless)."""

import re
import time

import pytest

from ws_testing import check, ros2

PARAM_SERVICES = ['describe_parameters', 'get_parameter_types', 'get_parameters',
                  'get_type_description', 'list_parameters', 'set_parameters',
                  'set_parameters_atomically']


@pytest.fixture(scope='module')
def turtlesim(module_turtlesim):
    """One turtlesim (in module_ros_env) for the tests that leave its graph as it is: the pen
    colour they set is not looked at, and background_r is changed by the last one only."""
    return module_turtlesim


@pytest.fixture
def own_turtlesim(launch):
    """A turtlesim of the test's own (in ros_env), for a test that adds a turtle."""
    process = launch('turtlesim', 'turtlesim_node', '--headless')
    process.wait_for_output(r'Spawning turtle \[turtle1\]')
    return process


def lines(*items):
    return ''.join(f'{item}\n' for item in items)



def test_service_list_is_the_tutorials(module_ros_env, turtlesim):
    first = ros2(module_ros_env, 'service', 'list')  # starts the daemon: complete, if not quick
    start = time.monotonic()
    result = ros2(module_ros_env, 'service', 'list')
    elapsed = time.monotonic() - start
    assert first.stdout == result.stdout
    check(result, lines(
        '/clear', '/kill', '/reset', '/spawn', '/turtle1/set_pen', '/turtle1/teleport_absolute',
        '/turtle1/teleport_relative', *(f'/turtlesim/{s}' for s in PARAM_SERVICES)))
    assert elapsed < 2.5, f'ros2 service list took {elapsed:.2f} s'


def test_service_type_interface_show_and_call_set_pen(module_ros_env, turtlesim):
    check(ros2(module_ros_env, 'service', 'type', '/turtle1/set_pen'), 'turtlesim/srv/SetPen\n')
    check(ros2(module_ros_env, 'interface', 'show', 'turtlesim/srv/SetPen'),
          'uint8 r\nuint8 g\nuint8 b\nuint8 width\nuint8 off\n---\n')
    check(ros2(module_ros_env, 'service', 'call', '/turtle1/set_pen', 'turtlesim/srv/SetPen',
               '{r: 255, g: 0, b: 0, width: 3, off: 0}'),
          'requester: making request: '
          'turtlesim.srv.SetPen_Request(r=255, g=0, b=0, width=3, off=0)\n\n'
          'response:\nturtlesim.srv.SetPen_Response()\n\n')


def test_service_call_spawn(ros_env, own_turtlesim):
    check(ros2(ros_env, 'service', 'call', '/spawn', 'turtlesim/srv/Spawn',
               "{x: 2, y: 2, theta: 0.2, name: ''}"),
          "requester: making request: turtlesim.srv.Spawn_Request(x=2.0, y=2.0, theta=0.2, "
          "name='')\n\nresponse:\nturtlesim.srv.Spawn_Response(name='turtle2')\n\n")
    bad = ros2(ros_env, 'service', 'call', '/turtle1/set_pen', 'turtlesim/srv/SetPen',
               '{r: 300}')
    check(bad, '', "Failed to populate field: 'r' must be an integer in [0, 255], got 300\n", 1)


def test_topic_echo_once_pose(module_ros_env, turtlesim):
    check(ros2(module_ros_env, 'topic', 'echo', '--once', '/turtle1/pose'),
          'x: 5.544444561004639\ny: 5.544444561004639\ntheta: 0.0\nlinear_velocity: 0.0\n'
          'angular_velocity: 0.0\n---\n')


def test_node_info_turtlesim(module_ros_env, turtlesim):
    check(ros2(module_ros_env, 'node', 'list'), '/turtlesim\n')
    check(ros2(module_ros_env, 'node', 'info', '/turtlesim'), lines(
        '/turtlesim',
        '  Subscribers:',
        '    /parameter_events: rcl_interfaces/msg/ParameterEvent',
        '    /turtle1/cmd_vel: geometry_msgs/msg/Twist',
        '  Publishers:',
        '    /parameter_events: rcl_interfaces/msg/ParameterEvent',
        '    /rosout: rcl_interfaces/msg/Log',
        '    /turtle1/color_sensor: turtlesim/msg/Color',
        '    /turtle1/pose: turtlesim/msg/Pose',
        '  Service Servers:',
        '    /clear: std_srvs/srv/Empty',
        '    /kill: turtlesim/srv/Kill',
        '    /reset: std_srvs/srv/Empty',
        '    /spawn: turtlesim/srv/Spawn',
        '    /turtle1/set_pen: turtlesim/srv/SetPen',
        '    /turtle1/teleport_absolute: turtlesim/srv/TeleportAbsolute',
        '    /turtle1/teleport_relative: turtlesim/srv/TeleportRelative',
        '    /turtlesim/describe_parameters: rcl_interfaces/srv/DescribeParameters',
        '    /turtlesim/get_parameter_types: rcl_interfaces/srv/GetParameterTypes',
        '    /turtlesim/get_parameters: rcl_interfaces/srv/GetParameters',
        '    /turtlesim/get_type_description: type_description_interfaces/srv/GetTypeDescription',
        '    /turtlesim/list_parameters: rcl_interfaces/srv/ListParameters',
        '    /turtlesim/set_parameters: rcl_interfaces/srv/SetParameters',
        '    /turtlesim/set_parameters_atomically: rcl_interfaces/srv/SetParametersAtomically',
        '  Service Clients:', '',
        '  Action Servers:',
        '    /turtle1/rotate_absolute: turtlesim/action/RotateAbsolute',
        '  Action Clients:', ''))


def test_topic_list_and_params(module_ros_env, turtlesim):
    check(ros2(module_ros_env, 'topic', 'list'), lines(
        '/parameter_events', '/rosout', '/turtle1/cmd_vel', '/turtle1/color_sensor',
        '/turtle1/pose'))
    check(ros2(module_ros_env, 'param', 'get', '/turtlesim', 'background_r'),
          'Integer value is: 69\n')
    check(ros2(module_ros_env, 'param', 'set', '/turtlesim', 'background_r', '150'),
          'Set parameter successful\n')
    check(ros2(module_ros_env, 'param', 'get', '/turtlesim', 'background_r'),
          'Integer value is: 150\n')
    listed = ros2(module_ros_env, 'param', 'list', '/turtlesim').stdout.splitlines()
    assert {'  background_b', '  background_g', '  background_r', '  holonomic',
            '  use_sim_time'} <= set(listed)
    refused = ros2(module_ros_env, 'param', 'set', '/turtlesim', 'background_r', '300')
    assert re.match(r'Setting parameter failed: ', refused.stderr), refused.stderr
