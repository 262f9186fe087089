"""velocity_smoother, collision_monitor and smoother_server over real DDS (no simulator),
brought up by a lifecycle_manager from one params file; and their arithmetic as functions.

velocity_smoother ramps a 0.5 m/s command at max_accel / smoothing_frequency per period
and brings the robot to a stop when commands stop; collision_monitor passes commands while
the scan is clear, stops for points inside its stop polygon and for a stale scan, with
upstream's lines; smoother_server smooths a zigzag path and answers a bad smoother id and an
empty path with SmoothPath's error codes.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from action_msgs.msg import GoalStatus
from geometry_msgs.msg import PoseStamped, Twist
from nav2_collision_monitor import geometry
from nav2_msgs.action import SmoothPath
from nav2_smoother.simple_smoother import SmootherParams
from nav2_smoother.simple_smoother import smooth as smooth_path
from nav2_velocity_smoother.smoothing import limits_error, smooth
from nav_msgs.msg import Path as PathMsg
from rclpy.action import ActionClient
from sensor_msgs.msg import LaserScan

from support import TestNode

PARAMS = """\
velocity_smoother:
  ros__parameters:
    smoothing_frequency: 20.0
    feedback: OPEN_LOOP
    max_velocity: [0.5, 0.0, 2.0]
    min_velocity: [-0.5, 0.0, -2.0]
    max_accel: [2.5, 0.0, 3.2]
    max_decel: [-2.5, 0.0, -3.2]
    velocity_timeout: 1.0
collision_monitor:
  ros__parameters:
    base_frame_id: base_footprint
    odom_frame_id: odom
    cmd_vel_in_topic: cmd_vel_smoothed
    cmd_vel_out_topic: cmd_vel
    state_topic: collision_monitor_state
    source_timeout: 1.0
    base_shift_correction: false
    stop_pub_timeout: 2.0
    polygons: [PolygonStop]
    PolygonStop:
      type: polygon
      points: "[[0.4, 0.3], [0.4, -0.3], [-0.3, -0.3], [-0.3, 0.3]]"
      action_type: stop
      min_points: 4
    observation_sources: [scan]
    scan:
      type: scan
      topic: scan
smoother_server:
  ros__parameters:
    smoother_plugins: [simple_smoother]
    simple_smoother:
      plugin: nav2_smoother::SimpleSmoother
      tolerance: 1.0e-10
      max_its: 1000
      do_refinement: true
lifecycle_manager:
  ros__parameters:
    autostart: true
    node_names: [velocity_smoother, collision_monitor, smoother_server]
"""


@pytest.fixture
def stack(launch, ros_env, tmp_path: Path):
    params = tmp_path / 'params.yaml'
    params.write_text(PARAMS)
    args = ['--ros-args', '--params-file', str(params)]
    launch('tf2_ros', 'static_transform_publisher', '--frame-id', 'base_footprint',
           '--child-frame-id', 'laser')
    servers = {  # the velocity smoother remapped as nav2_bringup does
        'velocity_smoother': launch('nav2_velocity_smoother', 'velocity_smoother', *args,
                                    '-r', 'cmd_vel:=cmd_vel_nav'),
        'collision_monitor': launch('nav2_collision_monitor', 'collision_monitor', *args),
        'smoother_server': launch('nav2_smoother', 'smoother_server', *args)}
    manager = launch('nav2_lifecycle_manager', 'lifecycle_manager', *args)
    manager.wait_for_output('Managed nodes are active', timeout=40)
    probe = TestNode(int(ros_env['ROS_DOMAIN_ID']))
    yield servers, probe
    probe.close()


def _scan(probe: TestNode, ranges: list[float]) -> LaserScan:
    msg = LaserScan()
    msg.header.frame_id = 'laser'
    msg.header.stamp = probe.node.get_clock().now().to_msg()
    msg.angle_min, msg.angle_increment = -0.2, 0.04
    msg.range_min, msg.range_max = 0.1, 10.0
    msg.ranges = ranges
    return msg


def test_velocity_smoother_ramps_up_and_stops(stack) -> None:
    _, probe = stack
    node = probe.node
    smoothed = probe.collect(Twist, '/cmd_vel_smoothed')
    pub = node.create_publisher(Twist, '/cmd_vel_nav', 10)
    command = Twist()
    command.linear.x = 0.8  # above max_velocity: clamped to 0.5
    timer = node.create_timer(0.05, lambda: pub.publish(command))
    probe.spin_until(lambda: any(m.linear.x >= 0.5 for m in smoothed), 15, 'full speed')
    ramp = [round(m.linear.x, 3) for m in smoothed if m.linear.x > 0.0]
    assert ramp[:4] == [0.125, 0.25, 0.375, 0.5], ramp  # 2.5 m/s^2 at 20 Hz
    assert max(m.linear.x for m in smoothed) == pytest.approx(0.5)
    node.destroy_timer(timer)
    count = len(smoothed)
    probe.spin_until(lambda: smoothed[-1].linear.x == 0.0, 5, 'the stop after the timeout')
    stopping = [round(m.linear.x, 3) for m in smoothed[count:] if m.linear.x < 0.5]
    assert stopping[:4] == [0.375, 0.25, 0.125, 0.0], stopping
    settled = len(smoothed)
    probe.spin_for(0.5)
    assert len(smoothed) == settled  # stopped: nothing more until the next command


def test_collision_monitor_stops_for_points_and_stale_scans(stack) -> None:
    servers, probe = stack
    node = probe.node
    out = probe.collect(Twist, '/cmd_vel')
    scan_pub = node.create_publisher(LaserScan, '/scan', 10)
    cmd_pub = node.create_publisher(Twist, '/cmd_vel_smoothed', 10)
    ranges = [5.0] * 10
    command = Twist()
    command.linear.x = 0.3

    def tick() -> None:
        if ranges:
            scan_pub.publish(_scan(probe, ranges))
        cmd_pub.publish(command)

    timer = node.create_timer(0.05, tick)
    probe.spin_until(lambda: out and out[-1].linear.x == pytest.approx(0.3), 15,
                     'the command passed through')
    monitor = servers['collision_monitor']

    def says_again(line: str) -> Callable[[], bool]:
        before = monitor.output.count(line)  # the start may have said it already
        return lambda: monitor.output.count(line) > before

    stop_line = says_again('Robot to stop due to PolygonStop polygon')
    ranges[:] = [0.2] * 10  # ten points 0.2 m ahead, inside PolygonStop
    probe.spin_until(stop_line, 10, 'the stop')
    probe.spin_until(lambda: out[-1].linear.x == 0.0, 5, 'a zero command')
    go_line = says_again('Robot to continue normal operation')
    ranges[:] = [5.0] * 10
    probe.spin_until(go_line, 10, 'the go-ahead')
    probe.spin_until(lambda: out[-1].linear.x == pytest.approx(0.3), 5, 'the command again')
    stale_line = says_again('Robot to stop due to invalid source')
    ranges.clear()  # the scan stops: 1 s later it is stale
    probe.spin_until(stale_line, 10, 'the stale stop')
    probe.spin_until(lambda: out[-1].linear.x == 0.0, 5, 'a zero command')
    node.destroy_timer(timer)


def _send(probe: TestNode, goal: SmoothPath.Goal) -> tuple[int, SmoothPath.Result]:
    client = ActionClient(probe.node, SmoothPath, '/smooth_path')
    try:
        assert client.wait_for_server(timeout_sec=15.0)
        future = client.send_goal_async(goal)
        probe.spin_until(future.done, 10.0, 'the goal to be answered')
        result = future.result().get_result_async()
        probe.spin_until(result.done, 10.0, 'the result')
        return result.result().status, result.result().result
    finally:
        client.destroy()


def test_smoother_server_smooths_and_refuses(stack) -> None:
    servers, probe = stack
    smoothed = probe.collect(PathMsg, '/plan_smoothed')
    path = PathMsg()
    path.header.frame_id = 'map'
    for i in range(30):  # a zigzag 0.02 m either side of y = 0
        pose = PoseStamped()
        pose.header.frame_id = 'map'
        pose.pose.position.x, pose.pose.position.y = i * 0.1, 0.02 * (-1) ** i
        pose.pose.orientation.w = 1.0
        path.poses.append(pose)
    goal = SmoothPath.Goal(path=path)
    goal.max_smoothing_duration.sec = 2
    status, result = _send(probe, goal)
    assert status == GoalStatus.STATUS_SUCCEEDED and result.error_code == 0
    assert result.was_completed
    y = [p.pose.position.y for p in result.path.poses]
    assert y[0] == pytest.approx(0.02) and y[-1] == pytest.approx(-0.02)  # ends kept
    assert max(abs(v) for v in y[2:-2]) < 0.01, y  # the zigzag flattened
    probe.spin_until(lambda: smoothed, 5, 'plan_smoothed')
    status, result = _send(probe, SmoothPath.Goal(path=path, smoother_id='nope'))
    assert status == GoalStatus.STATUS_ABORTED
    assert result.error_code == SmoothPath.Result.INVALID_SMOOTHER
    servers['smoother_server'].wait_for_output(
        'SmoothPath called with smoother name nope, which does not exist')
    status, result = _send(probe, SmoothPath.Goal(path=PathMsg()))
    assert status == GoalStatus.STATUS_ABORTED
    assert result.error_code == SmoothPath.Result.INVALID_PATH
    servers['smoother_server'].wait_for_output('Requested path to smooth is empty')


def test_velocity_smoother_refuses_a_positive_deceleration(launch) -> None:
    node = launch('nav2_velocity_smoother', 'velocity_smoother', '--ros-args', '-p',
                  'autostart_node:=true', '-p', 'max_decel:=[2.5, 0.0, -3.2]')
    node.wait_for_output('Positive values set of deceleration! These should be negative to '
                         'slow down!', timeout=15)
    node.wait_for_output('Auto-starting node velocity_smoother failed to configure!')


# --- the arithmetic -------------------------------------------------------------------


def test_smoothing_steps_and_scaling() -> None:
    accel, decel = [2.5, 0.0, 3.2], [-2.5, 0.0, -3.2]
    assert smooth([0.0, 0.0, 0.0], [0.5, 0.0, 0.0], accel, decel, 20.0, False)[0] == 0.125
    # decelerating and crossing zero use max_decel
    assert smooth([0.1, 0.0, 0.0], [-0.5, 0.0, 0.0], accel, decel, 20.0, False)[0] == \
        pytest.approx(-0.025)
    # scaled: the angular step (0.16 of 1.0) limits both axes to the same fraction
    out = smooth([0.0, 0.0, 0.0], [0.5, 0.0, 1.0], accel, decel, 20.0, True)
    assert out[2] == pytest.approx(0.16) and out[0] == pytest.approx(0.08)
    assert limits_error([1, 0, 1], [-1, 0, -1], [1, 0, 1], [-1, 0, -1], [0, 0]) is not None
    assert 'negative to slow down' in limits_error([1, 0, 1], [-1, 0, -1], [1, 0, 1],
                                                   [1, 0, -1], [0, 0, 0])


def test_collision_geometry() -> None:
    square = np.array([[0.5, 0.5], [0.5, -0.5], [-0.5, -0.5], [-0.5, 0.5]])
    points = np.array([[0.0, 0.0], [0.49, 0.2], [0.6, 0.0], [2.0, 2.0]])
    assert geometry.points_in_polygon(points, square) == 2
    assert geometry.points_in_circle(points, 0.6) == 2  # (0.6, 0) on the edge: out
    wall = np.array([[1.5, y] for y in np.linspace(-0.3, 0.3, 7)])

    def inside(p: np.ndarray) -> int:
        return geometry.points_in_polygon(p, square)

    # 1.0 m to the wall's face at 0.5 m/s: the 7 points enter after ~2 s of motion
    t = geometry.collision_time(wall, inside, (0.5, 0.0, 0.0), 3.0, 0.1, 6)
    assert 1.8 <= t <= 2.1, t
    assert geometry.collision_time(wall, inside, (0.5, 0.0, 0.0), 1.0, 0.1, 6) == -1.0
    assert geometry.is_less((0.1, 0.0, 0.0), (0.2, 0.0, 0.0))
    with pytest.raises(ValueError):
        geometry.parse_points('[[0, 0], [1, 1]]')


def test_simple_smoother_keeps_ends_and_straightens() -> None:
    x = np.arange(40) * 0.05
    y = np.where(np.arange(40) < 20, 0.0, (np.arange(40) - 20) * 0.05)  # a right-angle bend
    xy, yaw, done = smooth_path(np.stack([x, y], axis=1), np.zeros(40), SmootherParams(),
                                None, 1.0)
    assert done
    assert tuple(xy[0]) == (0.0, 0.0) and tuple(xy[-1]) == (x[-1], y[-1])
    corner = xy[20]
    assert corner[1] > 0.02  # the corner cut
    assert math.isclose(yaw[0], math.atan2(xy[1, 1] - xy[0, 1], xy[1, 0] - xy[0, 0]))
    started = time.monotonic()
    short = smooth_path(np.stack([x[:8], y[:8]], axis=1), np.zeros(8), SmootherParams(),
                        None, 1.0)
    assert time.monotonic() - started < 1.0
    assert np.array_equal(short[0], np.stack([x[:8], y[:8]], axis=1))  # < 10 poses: as is
