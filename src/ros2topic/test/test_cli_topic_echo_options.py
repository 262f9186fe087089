"""`ros2 topic echo`'s output options, `topic hz --filter`, `topic pub`'s wait for
subscriptions and `ros2topic.api`, each with ros2cli's exact output (as upstream's
ros2topic tests expect it), against a probe node publishing on the test's domain."""

import subprocess
import sys
import time

import pytest

from ws_testing import Background, RosProcess, TestNode, check, interface_type, ros2

HELLO = 'hello'


@pytest.fixture(scope='module')
def publishing(module_ros_env):
    """A probe publishing /words ('hello'), /point, /polygon and /counted ('0', '1', ...)
    at 10 Hz, and a simulated /clock ten times as fast as the wall clock (one simulated
    second per message), spun in the background for the whole module."""
    string = interface_type('std_msgs/msg/String')
    point = interface_type('geometry_msgs/msg/Point')
    polygon = interface_type('geometry_msgs/msg/Polygon')
    point32 = interface_type('geometry_msgs/msg/Point32')
    clock = interface_type('rosgraph_msgs/msg/Clock')
    probe = TestNode(int(module_ros_env['ROS_DOMAIN_ID']), 'echo_options_probe')
    node = probe.node
    publishers = {name: node.create_publisher(kind, name, 10) for name, kind in (
        ('/words', string), ('/point', point), ('/polygon', polygon), ('/counted', string),
        ('/clock', clock))}
    shape = polygon(points=[point32(x=1.0), point32(y=2.0)])
    counter = [0]

    def publish() -> None:
        publishers['/words'].publish(string(data=HELLO))
        publishers['/point'].publish(point(x=1.5, y=2.0, z=-1.0))
        publishers['/polygon'].publish(shape)
        publishers['/counted'].publish(string(data=str(counter[0])))
        counter[0] += 1
        tick = clock()
        tick.clock.sec = counter[0]
        publishers['/clock'].publish(tick)

    node.create_timer(0.1, publish)
    with Background(probe):
        yield module_ros_env
    probe.close()



def test_echo_formats(publishing):
    env = publishing
    check(ros2(env, 'topic', 'echo', '--once', '--no-str', '/words'),
          "data: '<string length: <5>>'\n---\n")
    check(ros2(env, 'topic', 'echo', '--once', '--truncate-length', '3', '/words'),
          'data: hel...\n---\n')
    check(ros2(env, 'topic', 'echo', '--once', '--csv', '/point'), '1.5,2.0,-1.0\n')
    check(ros2(env, 'topic', 'echo', '--once', '--no-arr', '/polygon'),
          "points: '<sequence type: geometry_msgs/msg/Point32, length: 2>'\n---\n")
    # The serialized CDR bytes: encapsulation header, length 6, 'hello\0', padding.
    check(ros2(env, 'topic', 'echo', '--once', '--raw', '/words', 'std_msgs/msg/String'),
          "b'\\x00\\x01\\x00\\x00\\x06\\x00\\x00\\x00hello\\x00\\x00\\x00'\n---\n")


def test_echo_field_filter_and_timeout(publishing):
    env = publishing
    check(ros2(env, 'topic', 'echo', '--once', '--field', 'x', '/point'), '1.5\n---\n')
    check(ros2(env, 'topic', 'echo', '--once', '--field', 'nope', '/point'), '',
          "Invalid field 'nope': 'Point' object has no attribute 'nope'\n", 1)
    check(ros2(env, 'topic', 'echo', '--field', '.', '/point'), '',
          "Invalid field value '.'\n", 1)
    check(ros2(env, 'topic', 'echo', '--once', '--filter', "m.data == 'hello'", '/words'),
          'data: hello\n---\n')
    # --timeout ends the echo quietly (exit 0), here with every message filtered out.
    start = time.monotonic()
    check(ros2(env, 'topic', 'echo', '--timeout', '1', '--filter', "m.data == 'bye'",
               '/words'), '')
    assert time.monotonic() - start < 10
    check(ros2(env, 'topic', 'echo', '--once', '--filter', 'm.nope', '/words'), '',
          "--filter: 'm.nope' failed: AttributeError(\"'String' object has no attribute "
          "'nope'\")\n", 1)


def test_echo_without_publisher_gives_up_once_the_graph_is_known(publishing):
    # ros2cli's echo does not wait for the topic: with every participant on the host met
    # and none publishing it, the type cannot be known.
    start = time.monotonic()
    check(ros2(publishing, 'topic', 'echo', '/nobody_publishes'),
          'WARNING: topic [/nobody_publishes] does not appear to be published yet\n',
          'Could not determine the type for the passed topic\n', 1)
    assert time.monotonic() - start < 4.0  # it used to wait for the topic for 4 s


def test_hz_filter(publishing, tmp_path):
    # Every other message of 10 Hz passes: about 5 Hz.
    hz = RosProcess(['ros2', 'topic', 'hz', '--filter', 'int(m.data) % 2 == 0', '/counted'],
                    publishing, tmp_path / 'hz.log')
    try:
        match = hz.wait_for_output(r'average rate: (\d+\.\d{3})\n\tmin: \d+\.\d{3}s max: '
                                   r'\d+\.\d{3}s std dev: \d+\.\d{5}s window: (\d+)', timeout=20)
    finally:
        hz.stop()
    assert 3.5 < float(match.group(1)) < 6.5, hz.output


def test_hz_and_bw_in_simulated_time(publishing, tmp_path):
    # -s: the node's clock follows /clock, one simulated second per message of /counted.
    hz = RosProcess(['ros2', 'topic', 'hz', '-s', '/counted'], publishing, tmp_path / 'hz.log')
    bw = RosProcess(['ros2', 'topic', 'bw', '-s', '/words'], publishing, tmp_path / 'bw.log')
    try:
        rate = hz.wait_for_output(r'average rate: (\d+\.\d{3})\n', timeout=20)
        # 'hello' is 16 bytes serialized: about 16 B per simulated second (a report over ten
        # messages or more: over n messages it is 16 n / (n - 1) B/s).
        size = bw.wait_for_output(r'(\d+) B/s from [1-9]\d+ messages\n\tMessage size mean: 16 B '
                                  r'min: 16 B max: 16 B\n', timeout=20)
    finally:
        hz.stop()
        bw.stop()
    assert 0.8 < float(rate.group(1)) < 1.25, hz.output
    assert 12 <= int(size.group(1)) <= 20, bw.output


def test_pub_wait_for_subscriptions(publishing):
    env = publishing
    check(ros2(env, 'topic', 'pub', '-t', '5', '--max-wait-time-secs', '1', '/nobody_listens',
               'std_msgs/msg/String', 'data: x'),
          'Waiting for at least 1 matching subscription(s)...\n' * 2,
          'Timed out waiting for subscribers: Expected 1 subcribers but only got 0 '
          'subscribers\n', 1)
    check(ros2(env, 'topic', 'pub', '--max-wait-time-secs', '1', '/nobody_listens',
               'std_msgs/msg/String', 'data: x'), '',
          '--max-wait-time-secs option is only effective with --wait-matching-subscriptions, '
          '--once or --times\n', 1)
    check(ros2(env, 'topic', 'pub', '--once', '-w', '0', '--stdin', '/nobody_listens',
               'std_msgs/msg/String', stdin='data: from stdin\n'),
          "publisher: beginning loop\npublishing #1: std_msgs.msg.String(data='from stdin')\n\n")


def test_ros2topic_api(publishing):
    """Upstream's ros2topic.api and verb classes, as fixture nodes and tools import them."""
    script = '''
import time

import rclpy
from rclpy.qos import DurabilityPolicy, ReliabilityPolicy
from ros2topic.api import (get_msg_class, get_topic_names, get_topic_names_and_types,
                           qos_profile_from_short_keys)
profile = qos_profile_from_short_keys('sensor_data', reliability='reliable',
                                      durability='transient_local', depth=3)
assert profile.reliability == ReliabilityPolicy.RELIABLE
assert profile.durability == DurabilityPolicy.TRANSIENT_LOCAL and profile.depth == 3
rclpy.init()
node = rclpy.create_node('api_user')
deadline = time.monotonic() + 20
while '/point' not in get_topic_names(node=node):
    assert time.monotonic() < deadline, 'no /point'
    rclpy.spin_once(node, timeout_sec=0.1)
print(dict(get_topic_names_and_types(node=node))['/point'])
print(get_msg_class(node, '/point').__name__)
print(get_msg_class(node, '/nobody_publishes'))
# ros2cli's verb classes, driven from Python: options not given take their defaults.
from argparse import Namespace
from ros2topic.verb.info import InfoVerb
print(InfoVerb().main(args=Namespace(topic_name='/nobody_publishes', spin_time=1.0)))
'''
    result = subprocess.run([sys.executable, '-c', script], env=publishing, capture_output=True,
                            text=True, timeout=60)
    check(result, "['geometry_msgs/msg/Point']\nPoint\n"
          'WARNING: topic [/nobody_publishes] does not appear to be published yet\nNone\n'
          "Unknown topic '/nobody_publishes'\n")
