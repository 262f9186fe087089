"""Every node that stands in for an upstream Jazzy node shows the graph what upstream's shows.

Each live node's `ros2 node info` and `ros2 param list` are compared, whole, with lists taken
from upstream's sources (facts only):

- ros/ros_tutorials turtlesim (rclcpp): turtle_frame.cpp declares background_r/g/b and
  holonomic, serves clear/reset/spawn/kill and subscribes to /parameter_events; turtle.cpp
  gives each turtle cmd_vel, pose, color_sensor, set_pen, teleport_absolute/relative and the
  rotate_absolute action; tutorials/teleop_turtle_key.cpp (node teleop_turtle) declares
  scale_angular/scale_linear, publishes turtle1/cmd_vel and is a turtle1/rotate_absolute action
  client; tutorials/mimic.cpp (turtle_mimic) maps input/pose to output/cmd_vel;
  tutorials/draw_square.cpp publishes turtle1/cmd_vel, subscribes to turtle1/pose and is a
  client of reset.
- ros2/rclcpp (jazzy) node.cpp: every rclcpp node declares the read-only
  qos_overrides./parameter_events.publisher.{depth,durability,history,reliability}, and its
  time source subscribes to /parameter_events; rclcpp and rclpy nodes both declare use_sim_time
  and start_type_description_service, publish /parameter_events and /rosout and serve the six
  parameter services plus get_type_description.
- ros2/demos demo_nodes_cpp parameter_blackboard.cpp: an rclcpp node that allows undeclared
  parameters, declares those it is given, and logs how many it serves (list_parameters,
  recursive) once constructed.
- ros2/demos demo_nodes_cpp talker.cpp / listener.cpp: rclcpp nodes publishing / subscribing
  /chatter (std_msgs/msg/String), no parameters of their own.
- ros2/demos demo_nodes_py add_two_ints_server/add_two_ints_client (rclpy; the course's
  my_robot_controller nodes carry these node names): /add_two_ints server and client, no
  parameters of their own.

No upstream node declares service_configure_introspection unless it is demo_nodes_cpp's
introspection demo: ours declare it only when asked at start (last test).
"""

from __future__ import annotations

import os
import pty
import subprocess
from collections.abc import Iterator

import pytest

from support import TestNode, executable, ros2

PARAM_SERVICES = (('describe_parameters', 'rcl_interfaces/srv/DescribeParameters'),
                  ('get_parameter_types', 'rcl_interfaces/srv/GetParameterTypes'),
                  ('get_parameters', 'rcl_interfaces/srv/GetParameters'),
                  ('get_type_description', 'type_description_interfaces/srv/GetTypeDescription'),
                  ('list_parameters', 'rcl_interfaces/srv/ListParameters'),
                  ('set_parameters', 'rcl_interfaces/srv/SetParameters'),
                  ('set_parameters_atomically', 'rcl_interfaces/srv/SetParametersAtomically'))
EVENTS = ('/parameter_events', 'rcl_interfaces/msg/ParameterEvent')
ROSOUT = ('/rosout', 'rcl_interfaces/msg/Log')
TWIST = 'geometry_msgs/msg/Twist'
POSE = 'turtlesim/msg/Pose'
ROTATE = ('/turtle1/rotate_absolute', 'turtlesim/action/RotateAbsolute')
QOS = tuple(f'qos_overrides./parameter_events.publisher.{policy}'
            for policy in ('depth', 'durability', 'history', 'reliability'))
AUTOMATIC = ('start_type_description_service', 'use_sim_time')
RCLCPP_PARAMETERS = (*QOS, *AUTOMATIC)
RCLPY_PARAMETERS = AUTOMATIC


class Upstream:
    """What upstream's node of this name shows: sorted (name, type) pairs and parameter names."""

    def __init__(self, name: str, *, subscribers=(), publishers=(), services=(), clients=(),
                 action_servers=(), action_clients=(), parameters=(), rclcpp: bool = True):
        self.name = name
        self.subscribers = sorted({*subscribers, *((EVENTS,) if rclcpp else ())})
        self.publishers = sorted({*publishers, EVENTS, ROSOUT})
        self.services = sorted({*services, *((f'/{name}/{service}', kind)
                                            for service, kind in PARAM_SERVICES)})
        self.clients = sorted(clients)
        self.action_servers = sorted(action_servers)
        self.action_clients = sorted(action_clients)
        self.parameters = sorted({*parameters,
                                  *(RCLCPP_PARAMETERS if rclcpp else RCLPY_PARAMETERS)})

    def node_info(self) -> str:
        """`ros2 node info /name` as Jazzy's ros2node prints it (an empty section: one blank
        line)."""
        out = [f'/{self.name}']
        for title, entries in (('Subscribers', self.subscribers), ('Publishers', self.publishers),
                               ('Service Servers', self.services),
                               ('Service Clients', self.clients),
                               ('Action Servers', self.action_servers),
                               ('Action Clients', self.action_clients)):
            out.append(f'  {title}:')
            out.extend([f'    {name}: {kind}' for name, kind in entries] or [''])
        return ''.join(f'{line}\n' for line in out)

    def param_list(self) -> str:
        return ''.join(f'  {name}\n' for name in self.parameters)


TURTLESIM = Upstream(
    'turtlesim',
    subscribers=[('/turtle1/cmd_vel', TWIST)],
    publishers=[('/turtle1/color_sensor', 'turtlesim/msg/Color'), ('/turtle1/pose', POSE)],
    services=[('/clear', 'std_srvs/srv/Empty'), ('/kill', 'turtlesim/srv/Kill'),
              ('/reset', 'std_srvs/srv/Empty'), ('/spawn', 'turtlesim/srv/Spawn'),
              ('/turtle1/set_pen', 'turtlesim/srv/SetPen'),
              ('/turtle1/teleport_absolute', 'turtlesim/srv/TeleportAbsolute'),
              ('/turtle1/teleport_relative', 'turtlesim/srv/TeleportRelative')],
    action_servers=[ROTATE],
    parameters=['background_b', 'background_g', 'background_r', 'holonomic'])
TELEOP = Upstream('teleop_turtle', publishers=[('/turtle1/cmd_vel', TWIST)],
                  action_clients=[ROTATE], parameters=['scale_angular', 'scale_linear'])
MIMIC = Upstream('turtle_mimic', subscribers=[('/input/pose', POSE)],
                 publishers=[('/output/cmd_vel', TWIST)])
DRAW_SQUARE = Upstream('draw_square', subscribers=[('/turtle1/pose', POSE)],
                       publishers=[('/turtle1/cmd_vel', TWIST)],
                       clients=[('/reset', 'std_srvs/srv/Empty')])
PARAMETER_BLACKBOARD = Upstream('parameter_blackboard')
ADD_TWO_INTS = ('/add_two_ints', 'example_interfaces/srv/AddTwoInts')
ADD_SERVER = Upstream('add_two_ints_server', services=[ADD_TWO_INTS], rclcpp=False)
ADD_CLIENT = Upstream('add_two_ints_client', clients=[ADD_TWO_INTS], rclcpp=False)
CHATTER = ('/chatter', 'std_msgs/msg/String')
TALKER = Upstream('talker', publishers=[CHATTER])
LISTENER = Upstream('listener', subscribers=[CHATTER])


def wait_until_discovered(env: dict[str, str], node: Upstream) -> None:
    """Until another participant sees every plain topic and service of `node` (the CLI's
    answer is then compared whole: a missing or extra entry fails there)."""
    probe = TestNode(int(env['ROS_DOMAIN_ID']))
    graph = probe.node

    def seen() -> bool:
        if node.name not in graph.get_node_names():
            return False
        found = {
            'subscribers': graph.get_subscriber_names_and_types_by_node(node.name, '/'),
            'publishers': graph.get_publisher_names_and_types_by_node(node.name, '/'),
            'services': graph.get_service_names_and_types_by_node(node.name, '/'),
            'clients': graph.get_client_names_and_types_by_node(node.name, '/'),
        }
        return all({name for name, _ in getattr(node, kind)} <= {name for name, _ in entries}
                   for kind, entries in found.items())
    try:
        probe.spin_until(seen, 20, f'the entities of /{node.name}')
    finally:
        probe.close()


def assert_like_upstream(env: dict[str, str], node: Upstream) -> None:
    wait_until_discovered(env, node)
    info = ros2(env, 'node', 'info', f'/{node.name}')
    assert (info.stdout, info.stderr, info.returncode) == (node.node_info(), '', 0)
    params = ros2(env, 'param', 'list', f'/{node.name}')
    assert (params.stdout, params.stderr, params.returncode) == (node.param_list(), '', 0)


@pytest.fixture(scope='module')
def teleop(module_ros_env, tmp_path_factory) -> Iterator[subprocess.Popen]:
    """turtle_teleop_key on a pseudo-terminal, as a user starts it; 'q' ends it."""
    controller, terminal = pty.openpty()
    log = open(tmp_path_factory.mktemp('teleop') / 'teleop.log', 'wb')
    process = subprocess.Popen([executable('turtlesim', 'turtle_teleop_key')],
                               env=module_ros_env, stdin=terminal, stdout=log,
                               stderr=subprocess.STDOUT, start_new_session=True)
    yield process
    os.write(controller, b'q')
    try:
        process.wait(timeout=5)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()
    os.close(controller)
    os.close(terminal)
    log.close()


def test_turtlesim_is_upstreams(module_ros_env, module_turtlesim):
    assert_like_upstream(module_ros_env, TURTLESIM)


def test_teleop_is_upstreams(module_ros_env, module_turtlesim, teleop):
    assert_like_upstream(module_ros_env, TELEOP)


def test_mimic_is_upstreams(module_ros_env, module_launch):
    module_launch('turtlesim', 'mimic')
    assert_like_upstream(module_ros_env, MIMIC)


def test_parameter_blackboard_is_demo_nodes_cpps(module_ros_env, module_launch):
    blackboard = module_launch('demo_nodes_cpp', 'parameter_blackboard')
    # rclcpp has declared its six parameters by the time the constructor logs.
    blackboard.wait_for_output(r"^\[INFO\] \[[\d.]+\] \[parameter_blackboard\]: Parameter "
                               r"blackboard node named '/parameter_blackboard' ready, and serving "
                               f"'{len(PARAMETER_BLACKBOARD.parameters)}' parameters already!$")
    assert_like_upstream(module_ros_env, PARAMETER_BLACKBOARD)


def test_talker_and_listener_are_demo_nodes_cpps(module_ros_env, module_launch):
    talker = module_launch('demo_nodes_cpp', 'talker')
    listener = module_launch('demo_nodes_cpp', 'listener')
    listener.wait_for_output('I heard', timeout=20)
    assert_like_upstream(module_ros_env, TALKER)
    assert_like_upstream(module_ros_env, LISTENER)
    assert talker.stop() == 0 and listener.stop() == 0


def test_add_two_ints_server_is_demo_nodes_pys(module_ros_env, module_launch):
    module_launch('my_robot_controller', 'add_two_ints_server').wait_for_output(
        'Ready to add two ints')
    assert_like_upstream(module_ros_env, ADD_SERVER)


def test_clients_without_their_server_are_upstreams(ros_env, launch):
    # A domain of their own: no turtlesim to reset, no server to answer the client (it keeps
    # waiting, so it is still there to be asked about).
    launch('turtlesim', 'draw_square')
    launch('my_robot_controller', 'add_two_ints_client').wait_for_output(
        'service /add_two_ints not available, waiting again')
    assert_like_upstream(ros_env, DRAW_SQUARE)
    assert_like_upstream(ros_env, ADD_CLIENT)


@pytest.mark.parametrize('asked', [
    ['--service-introspection', 'metadata'],
    ['--ros-args', '-p', 'service_configure_introspection:=metadata'],
], ids=['flag', 'override'])
def test_introspection_parameter_only_when_asked(ros_env, launch, asked):
    launch('turtlesim', 'turtlesim_node', '--headless', *asked).wait_for_output(
        r'Spawning turtle \[turtle1\]')
    wait_until_discovered(ros_env, TURTLESIM)
    listed = ros2(ros_env, 'param', 'list', '/turtlesim')
    with_it = sorted([*TURTLESIM.parameters, 'service_configure_introspection'])
    assert listed.stdout == ''.join(f'  {name}\n' for name in with_it), listed.stderr
    got = ros2(ros_env, 'param', 'get', '/turtlesim', 'service_configure_introspection')
    assert got.stdout == 'String value is: metadata\n', got.stderr
    topics = ros2(ros_env, 'topic', 'list', '--include-hidden-topics').stdout
    assert '/clear/_service_event' in topics.splitlines(), topics
