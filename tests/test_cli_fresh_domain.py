"""The first command in a fresh domain: verbs that adapt to the graph see what is there.

`ros2 topic echo` of a latched topic typed right after its publisher started, in a domain
where no `ros2` daemon ran yet, used to pick its QoS before its node knew the publisher: it
subscribed volatile and printed nothing (2 of 5 tries). Now its subscription follows the
publishers (ros2topic/api/adaptive_subscription.py), and `ros2 bag record` meets the graph
before it says "Recording...".
"""

from __future__ import annotations

import re
import sys
from contextlib import ExitStack
from pathlib import Path

from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from ros2cli.daemon import protocol
from std_msgs.msg import String

from support import RosProcess, executable, leased_domain, ros_environment, stop_daemon

TRIES = 20
AT_ONCE = 10  # tries side by side, each in a domain of its own
RECORD_LOG = r'\[INFO\] \[\d+\.\d+\] \[rosbag2_recorder\]: '

# A plain rclpy node (announced at Fast DDS's 3 s period, unlike node_runtime's) that
# publishes one latched message and spins.
LATCHED_TALKER = '''
import rclpy
from rclpy.qos import DurabilityPolicy, QoSProfile
from std_msgs.msg import String

rclpy.init()
node = rclpy.create_node('latched_talker')
publisher = node.create_publisher(
    String, '/latched', QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL))
publisher.publish(String(data='hello latched'))
print('published', flush=True)
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
'''

# A plain rclpy AddTwoInts server whose introspection events carry the contents.
INTROSPECTED_SERVER = '''
import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.qos import qos_profile_system_default
from rclpy.service_introspection import ServiceIntrospectionState

rclpy.init()
node = rclpy.create_node('add_two_ints_server')
service = node.create_service(AddTwoInts, '/add_two_ints', lambda request, response: response)
service.configure_introspection(node.get_clock(), qos_profile_system_default,
                                ServiceIntrospectionState.CONTENTS)
print('serving', flush=True)
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
'''


def fresh_env(domain: int) -> dict[str, str]:
    """The domain's environment, with no `ros2` daemon running there."""
    env = ros_environment(domain)
    stop_daemon(env)
    assert not protocol.socket_path(env).exists(), f'a daemon still serves domain {domain}'
    return env


def latched_publisher(index: int, env: dict[str, str], log: Path) -> tuple[RosProcess, str,
                                                                                 str, str]:
    """(the process, its line once published, the topic, the line echo prints of it):
    every other one a static transform broadcaster on /tf_static."""
    if index % 2:
        child = f'robot_{index}'
        argv = [executable('tf2_ros', 'static_transform_publisher'), '--x', '1',
                '--frame-id', 'world', '--child-frame-id', child]
        return (RosProcess(argv, env, log), 'Spinning until stopped', '/tf_static',
                f'child_frame_id: {child}')
    return (RosProcess([sys.executable, '-c', LATCHED_TALKER], env, log), 'published',
            '/latched', 'data: hello latched')


def test_echo_of_a_latched_topic_typed_first_in_a_fresh_domain_prints_it(tmp_path):
    missed = []
    for batch in range(0, TRIES, AT_ONCE):
        with ExitStack() as stack:
            envs = [fresh_env(stack.enter_context(leased_domain()))
                    for _ in range(AT_ONCE)]
            for env in envs:
                stack.callback(stop_daemon, env)  # the echo's lookup started one
            started = []
            for offset, env in enumerate(envs):
                index = batch + offset
                publisher, ready, topic, line = latched_publisher(
                    index, env, tmp_path / f'{index:02d}-publisher.log')
                stack.callback(publisher.stop)
                started.append((index, env, publisher, ready, topic, line))
            echoes = []
            for index, env, publisher, ready, topic, line in started:
                publisher.wait_for_output(ready, timeout=30)
                # At once, as a user types it right after the publisher said it is up.
                echo = RosProcess(['ros2', 'topic', 'echo', topic], env,
                                  tmp_path / f'{index:02d}-echo.log')
                stack.callback(echo.stop)
                echoes.append((index, echo, line))
            for index, echo, line in echoes:
                try:
                    echo.wait_for_output(re.escape(line), timeout=30)
                except AssertionError as error:
                    missed.append(f'try {index}: {error}')
    assert not missed, '\n'.join(missed)


def test_echo_follows_a_latched_publisher_that_appears_later(launch, probe):
    """Subscribed before anyone publishes: the subscription becomes transient local (and
    reliable) when the publisher shows up, and prints its message once; with the durability
    given on the command line it stays as given."""
    adapting = launch(argv=['ros2', 'topic', 'echo', '/late', 'std_msgs/msg/String'])
    fixed = launch(argv=['ros2', 'topic', 'echo', '--qos-durability', 'volatile', '/late',
                         'std_msgs/msg/String'])
    names = {f'_ros2cli_{adapting.popen.pid}': 'adapting', f'_ros2cli_{fixed.popen.pid}': 'fixed'}

    def subscriptions() -> dict[str, tuple]:
        return {names[info.node_name]: (info.qos_profile.durability,
                                        info.qos_profile.reliability)
                for info in probe.node.get_subscriptions_info_by_topic('/late')
                if info.node_name in names}

    probe.spin_until(lambda: len(subscriptions()) == 2, 30, 'both echoes subscribed')
    sensor_data = (DurabilityPolicy.VOLATILE, ReliabilityPolicy.BEST_EFFORT)
    assert subscriptions() == {'adapting': sensor_data, 'fixed': sensor_data}

    publisher = probe.node.create_publisher(String, '/late', QoSProfile(
        depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
        reliability=ReliabilityPolicy.RELIABLE))
    publisher.publish(String(data='first'))
    adapting.wait_for_output('data: first', timeout=20)
    probe.spin_until(lambda: subscriptions()['adapting'] == (
        DurabilityPolicy.TRANSIENT_LOCAL, ReliabilityPolicy.RELIABLE), 10,
        'the echo to re-subscribe transient local and reliable')
    probe.spin_until(lambda: publisher.get_subscription_count() == 2, 10,
                     'both echoes matched')
    publisher.publish(String(data='second'))
    adapting.wait_for_output('data: second', timeout=20)
    fixed.wait_for_output('data: second', timeout=20)
    assert subscriptions()['fixed'] == sensor_data
    # The history the new subscription got repeated nothing the first one had printed.
    assert adapting.output == 'data: first\n---\ndata: second\n---\n', adapting.output
    assert 'incompatible' not in fixed.output + adapting.output


def test_bag_record_subscribes_to_an_existing_service_before_recording(tmp_path):
    """`ros2 bag record --service` in a fresh domain next to a plain rclpy server: the
    event topic is subscribed before "Recording...", as rosbag2 does (it was after it in 2
    of 5 tries)."""
    with ExitStack() as stack:
        envs = [fresh_env(stack.enter_context(leased_domain())) for _ in range(5)]
        servers = []
        for index, env in enumerate(envs):
            server = RosProcess([sys.executable, '-c', INTROSPECTED_SERVER], env,
                                tmp_path / f'{index}-server.log')
            stack.callback(server.stop)
            servers.append(server)
        recorders = []
        for index, (env, server) in enumerate(zip(envs, servers, strict=True)):
            server.wait_for_output('serving', timeout=30)
            recorder = RosProcess(
                ['ros2', 'bag', 'record', '--disable-keyboard-controls', '--service',
                 '/add_two_ints', '-o', str(tmp_path / f'bag{index}')], env,
                tmp_path / f'{index}-record.log')
            stack.callback(recorder.stop)
            recorders.append(recorder)
        for recorder in recorders:
            recorder.wait_for_output(RECORD_LOG + 'Recording...', timeout=30)
            subscribed = re.search(RECORD_LOG + re.escape(
                "Subscribed to topic '/add_two_ints/_service_event'"), recorder.output)
            recording = re.search(RECORD_LOG + r'Recording\.\.\.', recorder.output)
            assert subscribed and subscribed.start() < recording.start(), recorder.output
