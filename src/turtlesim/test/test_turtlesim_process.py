"""turtlesim_node start-up options, ROS graph and shutdown, each with its own process."""

from __future__ import annotations

import itertools
import os
import signal
import time

import pytest
from geometry_msgs.msg import Twist
from PySide6.QtGui import QImage
from rosgraph_msgs.msg import Clock
from turtlesim.msg import Pose

from ws_testing import turtle_qos

CENTER = 5.544444561004639


def start(launch, tmp_path, *args):
    process = launch('turtlesim', 'turtlesim_node', '--headless',
                     '--canvas-png', str(tmp_path / 'c.png'), *args)
    process.wait_for_output(r'Spawning turtle \[turtle1\]')
    return process


def visible(names_and_types):
    return sorted(name for name, _ in names_and_types
                  if not any(token.startswith('_') for token in name.split('/')))


def test_ros_graph_matches_upstream(launch, probe, tmp_path):
    start(launch, tmp_path)
    node = probe.node
    probe.spin_until(lambda: ('turtlesim', '/') in node.get_node_names_and_namespaces(), 10,
                     'the turtlesim node')
    expected_services = [
        '/clear', '/kill', '/reset', '/spawn', '/turtle1/set_pen',
        '/turtle1/teleport_absolute', '/turtle1/teleport_relative',
        '/turtlesim/describe_parameters', '/turtlesim/get_parameter_types',
        '/turtlesim/get_parameters', '/turtlesim/get_type_description',
        '/turtlesim/list_parameters', '/turtlesim/set_parameters',
        '/turtlesim/set_parameters_atomically']

    def services():
        return visible(node.get_service_names_and_types_by_node('turtlesim', '/'))

    probe.spin_until(lambda: services() == expected_services, 10, 'the upstream service list')
    all_services = [name for name, _ in
                    node.get_service_names_and_types_by_node('turtlesim', '/')]
    assert '/turtlesim/_save_canvas' in all_services
    assert visible(node.get_publisher_names_and_types_by_node('turtlesim', '/')) == [
        '/parameter_events', '/rosout', '/turtle1/color_sensor', '/turtle1/pose']
    assert visible(node.get_subscriber_names_and_types_by_node('turtlesim', '/')) == [
        '/parameter_events', '/turtle1/cmd_vel']
    topics = [name for name, _ in node.get_topic_names_and_types()]
    assert not [t for t in topics if t.endswith('_service_event')]  # introspection is off
    info = node.get_publishers_info_by_topic('/turtle1/pose')
    assert [(i.qos_profile.reliability.name, i.qos_profile.durability.name)
            for i in info] == [('RELIABLE', 'VOLATILE')]


@pytest.mark.parametrize('sig', [signal.SIGINT, signal.SIGTERM])
def test_shutdown_writes_png_and_exits_0(launch, tmp_path, sig):
    process = start(launch, tmp_path)
    time.sleep(0.3)
    os.killpg(process.popen.pid, sig)
    assert process.wait(timeout=10) == 0, process.output
    process.wait_for_output(rf'\[INFO\] .*\[turtlesim\]: Canvas written to {tmp_path}/c\.png$')
    assert 'Traceback' not in process.output
    assert 'Failed to publish' not in process.output
    image = QImage(str(tmp_path / 'c.png'))
    color = image.pixelColor(10, 10)
    assert (color.red(), color.green(), color.blue()) == (69, 86, 255)


def test_fixed_step_publishes_clock_and_moves_exactly(launch, probe, tmp_path):
    start(launch, tmp_path, '--fixed-step')
    clocks = probe.collect(Clock, '/clock')
    poses = probe.collect(Pose, '/turtle1/pose', turtle_qos())
    probe.spin_until(lambda: len(clocks) > 20 and poses, 10, '/clock and poses')
    stamps = [c.clock.sec * 10**9 + c.clock.nanosec for c in clocks]
    # /clock is best effort, keep last 1 (as rclcpp's): a loaded subscriber may miss a stamp,
    # but every step is exactly 16 ms of simulated time (never a wall-clock step).
    deltas = {b - a for a, b in itertools.pairwise(stamps)}
    assert 16_000_000 in deltas
    assert all(d > 0 and d % 16_000_000 == 0 for d in deltas), deltas
    publisher = probe.node.create_publisher(Twist, '/turtle1/cmd_vel', turtle_qos())
    probe.spin_until(lambda: publisher.get_subscription_count() > 0, 10, 'cmd_vel subscriber')
    twist = Twist()
    twist.linear.x = 2.0
    publisher.publish(twist)
    probe.spin_until(lambda: poses[-1].linear_velocity == 2.0, 3, 'motion')
    probe.spin_until(lambda: poses[-1].linear_velocity == 0.0, 5, 'the timeout')
    ticks_moving = sum(1 for p in poses if p.linear_velocity == 2.0)
    # 1 s of simulated time at exactly 0.016 s per tick, 0.032 m per tick
    assert ticks_moving in (62, 63)
    assert poses[-1].x == pytest.approx(CENTER + 0.032 * ticks_moving, abs=1e-4)


def test_introspection_contents_carries_requests(launch, probe, tmp_path):
    from turtlesim.srv import SetPen
    start(launch, tmp_path, '--service-introspection', 'contents')
    events = probe.collect(SetPen.Event, '/turtle1/set_pen/_service_event')
    client = probe.node.create_client(SetPen, '/turtle1/set_pen')
    assert client.wait_for_service(timeout_sec=10)
    probe.spin_for(0.5)
    future = client.call_async(SetPen.Request(r=7, g=8, b=9, width=4))
    probe.spin_until(future.done, 5, 'set_pen')
    probe.spin_until(lambda: len(events) >= 2, 5, 'introspection events')
    requests = [e.request[0] for e in events if e.request]
    assert [(r.r, r.g, r.b, r.width) for r in requests] == [(7, 8, 9, 4)]


def test_bad_command_line_parameter_falls_back_to_default(launch, tmp_path):
    process = start(launch, tmp_path, '--ros-args', '-p', 'background_r:=300')
    process.wait_for_output(r'\[ERROR\] .*Ignoring the command-line value of background_r; '
                            r'using the default 69')
