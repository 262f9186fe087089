"""`ros2 topic find/bw/delay`, `topic pub` with `header: auto` / `stamp: now`, and
`ros2 service echo` on services with introspection switched on by parameter."""

import re
import time

import pytest

from ws_testing import (
    RosProcess,
    TestNode,
    check,
    interface_type,
    ros2,
)

NUMBER = r'\d+\.\d+'


@pytest.fixture(scope='module')
def turtlesim(module_launch):
    # Introspection asked for at start (upstream turtlesim has no such parameter): the
    # parameter is then declared, introspection off until switched on by `param set`.
    process = module_launch('turtlesim', 'turtlesim_node', '--headless', '--ros-args', '-p',
                            'service_configure_introspection:=disabled')
    process.wait_for_output(r'Spawning turtle \[turtle1\]')
    return process


@pytest.fixture(scope='module')
def probe_in_module_domain(module_ros_env):
    node = TestNode(int(module_ros_env['ROS_DOMAIN_ID']))
    yield node
    node.close()


@pytest.fixture
def background(module_ros_env, tmp_path):
    """background('ros2', ...) runs a long-lived command; all are Ctrl-C'd at teardown."""
    started = []

    def start(*argv):
        process = RosProcess(list(argv), module_ros_env, tmp_path / f'{len(started)}.log')
        started.append(process)
        return process

    yield start
    for process in started:
        process.stop()



def test_find(module_ros_env, turtlesim):
    check(ros2(module_ros_env, 'topic', 'find', 'turtlesim/msg/Pose'), '/turtle1/pose\n')
    check(ros2(module_ros_env, 'topic', 'find', '-c', 'geometry_msgs/msg/Twist'), '1\n')
    check(ros2(module_ros_env, 'topic', 'find', '--spin-time', '1', 'std_msgs/msg/String'), '')


def test_bw_of_the_pose_topic(turtlesim, background):
    # turtlesim/msg/Pose: 4-byte CDR header + 5 float32 = 24 bytes, about 62 per second.
    bw = background('ros2', 'topic', 'bw', '/turtle1/pose')
    # Below 1000 B/s (a loaded machine) the sizes are printed in bytes instead.
    match = bw.wait_for_output(
        r'^Subscribed to \[/turtle1/pose\]\n(\d+(?:\.\d\d)?) (K?B)/s from (\d+) messages\n'
        r'\tMessage size mean: (0\.02 KB|24 B) min: \4 max: \4$', timeout=15)
    rate = float(match.group(1)) * (1000 if match.group(2) == 'KB' else 1)
    assert 300 < rate < 3000, bw.output


def test_pub_header_auto_is_stamped_and_delay_measures_it(module_ros_env, turtlesim,
                                                          background):
    topic = '/stamped'
    background('ros2', 'topic', 'pub', '-r', '20', topic, 'geometry_msgs/msg/PointStamped',
               '{header: auto, point: {x: 1.0}}')
    before = time.time()
    # With the type given, as ros2cli's echo does not wait for an unpublished topic's type.
    echoed = ros2(module_ros_env, 'topic', 'echo', '--once', topic,
                  'geometry_msgs/msg/PointStamped', '--timeout', '10')
    match = re.fullmatch(r'header:\n  stamp:\n    sec: (\d+)\n    nanosec: (\d+)\n'
                         r"  frame_id: ''\npoint:\n  x: 1\.0\n  y: 0\.0\n  z: 0\.0\n---\n",
                         echoed.stdout)
    assert match, echoed.stdout + echoed.stderr
    assert abs(int(match.group(1)) - before) < 30

    delay = background('ros2', 'topic', 'delay', topic)
    match = delay.wait_for_output(
        rf'^average delay: ({NUMBER})\n\tmin: {NUMBER}s max: {NUMBER}s std dev: {NUMBER}s '
        r'window: \d+$', timeout=15)
    assert float(match.group(1)) < 1.0, delay.output


def test_pub_stamp_now_and_delay_refuses_a_type_without_header(module_ros_env, turtlesim,
                                                               background):
    background('ros2', 'topic', 'pub', '-r', '20', '/when', 'rosgraph_msgs/msg/Clock',
               '{clock: now}')
    refused = ros2(module_ros_env, 'topic', 'pub', '--once', '/when',
                   'rosgraph_msgs/msg/Clock', '{clock: {sec: now}}')
    check(refused, '', "Failed to populate field: 'clock.sec' must be an integer in "
          '[-2147483648, 2147483647], got \'now\'\n', 1)
    echoed = ros2(module_ros_env, 'topic', 'echo', '--once', '/when', 'rosgraph_msgs/msg/Clock',
                  '--timeout', '10')
    sec = re.fullmatch(r'clock:\n  sec: (\d+)\n  nanosec: \d+\n---\n', echoed.stdout)
    assert sec and abs(int(sec.group(1)) - time.time()) < 30, echoed.stdout + echoed.stderr
    check(ros2(module_ros_env, 'topic', 'delay', '/turtle1/pose'), '',
          'turtlesim/msg/Pose has no header: the delay is measured from header.stamp (use a '
          'stamped type, e.g. geometry_msgs/msg/TwistStamped)\n', 1)


def test_service_echo_without_introspection_says_so(module_ros_env, turtlesim, background):
    echo = background('ros2', 'service', 'echo', '/clear')
    echo.wait_for_output(r"^No publishers on topic '/clear/_service_event'; is service "
                         r'introspection on the client or server enabled\?$')
    check(ros2(module_ros_env, 'service', 'echo', '/x', 'std_srvs/srv/Nope'), '',
          "The service type 'std_srvs/srv/Nope' is invalid\n", 1)


def _event_blocks(output: str) -> list[str]:
    """The echoed events from the first REQUEST_RECEIVED on: a call whose request event was
    sent before echo's subscription matched may still show its RESPONSE_SENT."""
    blocks = [block for block in output.split('---\n') if block.startswith('info:')]
    for index, block in enumerate(blocks):
        if 'event_type: REQUEST_RECEIVED' in block:
            return blocks[index:]
    return []


def _call_until_echoed(call, echo) -> list[str]:
    """Call (`call(attempt)`) until echo shows a call's two events, at most 10 times. Events
    sent before echo's subscription has matched the server's event publisher are lost
    (volatile, as in Jazzy), and a subscription seen in the graph may not have matched yet."""
    for attempt in range(1, 11):
        call(attempt)
        shown = time.monotonic() + 3.0
        while len(_event_blocks(echo.output)) < 2 and time.monotonic() < shown:
            time.sleep(0.05)
        if len(_event_blocks(echo.output)) >= 2:
            break
    blocks = _event_blocks(echo.output)
    assert len(blocks) >= 2, echo.output
    return blocks


def test_service_echo_after_switching_introspection_on(module_ros_env, turtlesim, background,
                                                       probe_in_module_domain):
    check(ros2(module_ros_env, 'param', 'set', '/turtlesim', 'service_configure_introspection',
               'contents'), 'Set parameter successful\n')
    echo = background('ros2', 'service', 'echo', '--flow-style', '/spawn')
    # --no-arr: arrays and sequences as upstream's '<... type: ...>' summaries.
    summaries = background('ros2', 'service', 'echo', '--no-arr', '/spawn')
    probe = probe_in_module_domain
    # Generous: echo may first start the daemon (~4 s of discovery) before it subscribes.
    probe.spin_until(lambda: probe.node.count_subscribers('/spawn/_service_event') >= 2, 30,
                     'the echo subscriptions')
    spawn = interface_type('turtlesim/srv/Spawn')

    def spawn_one(attempt: int) -> None:
        probe.call(spawn, '/spawn', spawn.Request(x=3.0, y=3.0, name=f'echoed{attempt}'))
    received, sent = _call_until_echoed(spawn_one, echo)[:2]
    assert re.fullmatch(
        r'info:\n  event_type: REQUEST_RECEIVED\n  stamp:\n    sec: \d+\n    nanosec: \d+\n'
        r'  client_gid: \[(\d+, ){15}\d+\]\n  sequence_number: \d+\n'
        r"request: \[\{x: 3\.0, y: 3\.0, theta: 0\.0, name: echoed\d+\}\]\nresponse: \[\]\n",
        received), received
    assert re.search(r'event_type: RESPONSE_SENT\n.*request: \[\]\nresponse: \[\{name: '
                     r'echoed\d+\}\]\n$', sent, re.DOTALL), sent
    summarised = _call_until_echoed(lambda attempt: spawn_one(10 + attempt), summaries)[0]
    assert re.fullmatch(
        r'info:\n  event_type: REQUEST_RECEIVED\n  stamp:\n    sec: \d+\n    nanosec: \d+\n'
        r"  client_gid: '<array type: uint8\[16\]>'\n  sequence_number: \d+\n"
        r"request: '<sequence type: turtlesim/srv/Spawn_Request\[1\], length: 1>'\n"
        r"response: '<sequence type: turtlesim/srv/Spawn_Response\[1\], length: 0>'\n",
        summarised), summarised
    refused = ros2(module_ros_env, 'param', 'set', '/turtlesim',
                   'service_configure_introspection', 'everything')
    assert refused.stderr == ('Setting parameter failed: parameter '
                              'service_configure_introspection must be one of disabled, '
                              "metadata, contents, got 'everything'\n")


def test_service_echo_add_two_ints_server(module_ros_env, module_launch, background,
                                          probe_in_module_domain):
    server = module_launch('my_robot_controller', 'add_two_ints_server', '--ros-args', '-p',
                           'service_configure_introspection:=metadata')
    server.wait_for_output('Ready to add two ints')
    echo = background('ros2', 'service', 'echo', '/add_two_ints')
    probe = probe_in_module_domain
    probe.spin_until(lambda: probe.node.count_subscribers('/add_two_ints/_service_event') >= 1,
                     30, 'the echo subscription')
    add = interface_type('example_interfaces/srv/AddTwoInts')

    def add_two_and_three(_attempt: int) -> None:
        assert probe.call(add, '/add_two_ints', add.Request(a=2, b=3)).sum == 5
    received = _call_until_echoed(add_two_and_three, echo)[0]
    # metadata only: the event says what happened, without the request's contents.
    assert re.fullmatch(
        r'info:\n  event_type: REQUEST_RECEIVED\n  stamp:\n    sec: \d+\n    nanosec: \d+\n'
        r'  client_gid:\n(  - \d+\n){16}  sequence_number: \d+\nrequest: \[\]\nresponse: \[\]\n',
        received), received
