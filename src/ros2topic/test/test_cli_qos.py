"""`ros2 topic pub/echo --qos-*`: the profile the options make, and ros2cli's incompatible-QoS
warnings, with the verb run by the CLI itself and by the `ros2` daemon."""

from __future__ import annotations

import re

import rclpy.qos
from rclpy.qos import (
    DurabilityPolicy,
    HistoryPolicy,
    QoSProfile,
    ReliabilityPolicy,
)
from ros2topic.api import qos as cli_qos
from std_msgs.msg import String

from ws_testing import Background, ros2, ros2_side_by_side

WARN = r'\[WARN\] \[\d+\.\d+\] \[_ros2cli_\d+\]: '


def test_the_written_out_short_keys_are_rclpys():
    assert cli_qos.PROFILES == rclpy.qos.QoSPresetProfiles.short_keys()
    assert cli_qos.HISTORY == rclpy.qos.QoSHistoryPolicy.short_keys()
    assert cli_qos.RELIABILITY == rclpy.qos.QoSReliabilityPolicy.short_keys()
    assert cli_qos.DURABILITY == rclpy.qos.QoSDurabilityPolicy.short_keys()
    assert cli_qos.LIVELINESS == rclpy.qos.QoSLivelinessPolicy.short_keys()


def test_pub_offers_what_the_options_say_and_echo_asks_for_it(launch, probe, ros_env):
    publisher = launch(argv=['ros2', 'topic', 'pub', '-r', '5', '--qos-durability',
                             'transient_local', '--qos-reliability', 'reliable',
                             '--qos-liveliness', 'manual_by_topic',
                             '--qos-liveliness-lease-duration-seconds', '3', '/latched',
                             'std_msgs/msg/String', 'data: kept'])
    publisher.wait_for_output('publishing #1')
    probe.spin_until(lambda: probe.node.get_publishers_info_by_topic('/latched'), 10,
                     'the publisher in the graph')
    offered = probe.node.get_publishers_info_by_topic('/latched')[0].qos_profile
    assert (offered.durability, offered.reliability, offered.liveliness) == (
        DurabilityPolicy.TRANSIENT_LOCAL, ReliabilityPolicy.RELIABLE,
        rclpy.qos.LivelinessPolicy.MANUAL_BY_TOPIC)
    assert offered.liveliness_lease_duration.nanoseconds == 3_000_000_000

    # --once runs in the daemon (started by the listing); --no-daemon in the CLI: both ask
    # for a latched, reliable sample and get one.
    assert '/latched' in ros2(ros_env, 'topic', 'list').stdout
    for extra in ([], ['--no-daemon']):
        echoed = ros2(ros_env, 'topic', 'echo', '--once', '--qos-durability', 'transient_local',
                      '--qos-reliability', 'reliable', '--qos-depth', '5', *extra, '/latched',
                      'std_msgs/msg/String')
        assert (echoed.stdout, echoed.stderr, echoed.returncode) == ("data: kept\n---\n", '',
                                                                    0), echoed
    bad = ros2(ros_env, 'topic', 'echo', '--qos-durability', 'forever', '/latched')
    assert bad.returncode == 2 and bad.stderr.splitlines()[-1] == (
        "ros2 topic echo: error: argument --qos-durability: invalid choice: 'forever' (choose "
        "from 'system_default', 'transient_local', 'volatile', 'unknown', 'best_available')")


def test_incompatible_qos_is_warned_in_the_cli_and_from_the_daemon(probe, ros_env, launch):
    volatile = probe.node.create_publisher(
        String, '/volatile', QoSProfile(depth=10, reliability=ReliabilityPolicy.BEST_EFFORT))
    latched = probe.node.create_subscription(
        String, '/wants_latched', lambda _m: None,
        QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                   history=HistoryPolicy.KEEP_LAST))
    assert latched and volatile
    assert '/volatile' in ros2(ros_env, 'topic', 'list').stdout  # the daemon knows the graph
    with Background(probe):
        # echo --once --timeout: run by the daemon; without --once: by the CLI itself. The
        # three wait out their own time limits: side by side.
        daemon, direct, pub = ros2_side_by_side(
            ros_env,
            ['topic', 'echo', '--once', '--timeout', '3', '--qos-reliability', 'reliable',
             '/volatile', 'std_msgs/msg/String'],
            ['topic', 'echo', '--timeout', '3', '--once', '--no-daemon', '--qos-reliability',
             'reliable', '/volatile', 'std_msgs/msg/String'],
            ['topic', 'pub', '-t', '1', '-w', '0', '--keep-alive', '2', '/wants_latched',
             'std_msgs/msg/String', 'data: x'])
    for result in (daemon, direct):
        assert re.search(WARN + re.escape(
            "New publisher discovered on topic '/volatile', offering incompatible QoS. No "
            'messages will be received from it. Last incompatible policy: RELIABILITY\n'),
            result.stderr), result
        # --timeout ends the echo quietly, as ros2cli's (exit 0, nothing printed).
        assert result.returncode == 0 and result.stdout == ''
    assert re.search(WARN + re.escape(
        "New subscription discovered on topic '/wants_latched', requesting incompatible QoS. "
        'No messages will be sent to it. Last incompatible policy: DURABILITY\n'),
        pub.stderr), pub
    assert pub.returncode == 0
