"""turtlesim_node as a real process over DDS: start-up, motion, pen and canvas, spawn, kill
and reset.

One turtlesim serves the whole module (conftest.py); every test starts from /reset, /clear and
default parameters, and reads only the log written after its start.
"""

from __future__ import annotations

import math
import re
import time

import pytest
from geometry_msgs.msg import Twist
from headless_turtlesim import BACKGROUND, CENTER, PEN, W, int_value, rgb
from rcl_interfaces.msg import ParameterType, ParameterValue
from std_srvs.srv import Empty
from turtlesim.msg import Color, Pose
from turtlesim.srv import Kill, SetPen, Spawn, TeleportAbsolute, TeleportRelative

# ---------------------------------------------------------------------------- start-up


def test_start_logs_and_initial_pose(ts):
    output = ts.process.output
    assert re.search(r'^\[INFO\] \[\d+\.\d+\] \[turtlesim\]: Starting turtlesim with node name '
                     r'/turtlesim$', output, re.MULTILINE), output
    assert ('[turtlesim]: Spawning turtle [turtle1] at x=[5.544445], y=[5.544445], '
            'theta=[0.000000]') in output
    pose = ts.latest_pose()
    assert (pose.x, pose.y, pose.theta) == (CENTER, CENTER, 0.0)
    assert (pose.linear_velocity, pose.angular_velocity) == (0.0, 0.0)


def test_pose_rate_is_62_5_hz(ts):
    poses = ts.collect(Pose, '/turtle1/pose')
    ts.probe.spin_until(lambda: poses, 5, 'the first pose')
    start_count, start = len(poses), time.monotonic()
    ts.probe.spin_for(3.0)
    rate = (len(poses) - start_count) / (time.monotonic() - start)
    assert rate == pytest.approx(62.5, abs=1.0)


def test_color_sensor_reads_path_layer_not_background(ts):
    colors = ts.collect(Color, '/turtle1/color_sensor')
    ts.probe.spin_until(lambda: colors, 5, 'a color_sensor message')
    assert (colors[-1].r, colors[-1].g, colors[-1].b) == (255, 255, 255)


# ---------------------------------------------------------------------------- motion


def test_cmd_vel_moves_then_times_out_after_one_second(ts):
    poses = ts.collect(Pose, '/turtle1/pose')
    ts.publish('/turtle1/cmd_vel', Twist())  # connect first; a zero command moves nothing
    ts.probe.spin_for(0.2)
    twist = Twist()
    twist.linear.x = 2.0
    ts.publish('/turtle1/cmd_vel', twist)
    sent = time.monotonic()
    ts.probe.spin_until(lambda: poses and poses[-1].linear_velocity == 2.0, 2, 'moving')
    ts.probe.spin_until(lambda: poses[-1].linear_velocity == 0.0, 3, 'the timeout')
    stopped_after = time.monotonic() - sent
    assert 0.9 < stopped_after < 1.4
    ts.probe.spin_for(0.2)
    pose = poses[-1]
    assert pose.x == pytest.approx(CENTER + 2.0, abs=0.15)  # 2 m/s for 1 s
    assert pose.y == pytest.approx(CENTER, abs=1e-5)


def test_linear_velocity_is_a_magnitude_and_angular_is_commanded(ts):
    poses = ts.collect(Pose, '/turtle1/pose')
    twist = Twist()
    twist.linear.x = -1.0
    twist.angular.z = 0.5
    ts.publish('/turtle1/cmd_vel', twist)
    ts.probe.spin_until(lambda: poses and poses[-1].angular_velocity == 0.5, 2, 'turning')
    assert poses[-1].linear_velocity == 1.0


def test_wall_warning_and_clamp(ts):
    ts.call(TeleportAbsolute, '/turtle1/teleport_absolute', x=20.0, y=3.0, theta=0.0)
    ts.wait_for_log(r'^\[WARN\] \[\d+\.\d+\] \[turtlesim\]: Oh no! I hit the wall! '
                    r'\(Clamping from \[x=20\.000000, y=8\.088889\]\)$')
    pose = ts.latest_pose()
    assert pose.x == pytest.approx(W)
    assert pose.y == pytest.approx(3.0)


def test_teleport_absolute_above_top_is_silently_clamped(ts):
    ts.call(TeleportAbsolute, '/turtle1/teleport_absolute', x=3.0, y=50.0, theta=1.0)
    pose = ts.latest_pose()
    assert (pose.x, pose.y) == pytest.approx((3.0, W))
    assert pose.theta == pytest.approx(1.0)
    assert 'hit the wall' not in ts.new_output()


def test_teleport_relative_rotates_then_moves(ts):
    ts.call(TeleportRelative, '/turtle1/teleport_relative', linear=1.0, angular=math.pi / 2)
    pose = ts.latest_pose()
    assert pose.x == pytest.approx(CENTER, abs=1e-5)
    assert pose.y == pytest.approx(CENTER + 1.0, abs=1e-5)
    assert pose.theta == pytest.approx(math.pi / 2, abs=1e-5)


def test_holonomic_parameter(ts):
    poses = ts.collect(Pose, '/turtle1/pose')
    sideways = Twist()
    sideways.linear.y = 1.0
    ts.publish('/turtle1/cmd_vel', sideways)
    ts.probe.spin_for(0.5)
    assert poses[-1].y == pytest.approx(CENTER, abs=1e-6)  # not holonomic: vy ignored
    result = ts.set_parameter('holonomic', ParameterValue(
        type=ParameterType.PARAMETER_BOOL, bool_value=True))
    assert result.successful
    ts.publish('/turtle1/cmd_vel', sideways)
    ts.probe.spin_until(lambda: poses[-1].y > CENTER + 0.2, 2, 'sideways motion')
    assert poses[-1].x == pytest.approx(CENTER, abs=1e-4)
    assert poses[-1].linear_velocity == 1.0


# ---------------------------------------------------------------------------- pen and canvas


def draw_vertical_line(ts, rgb_pen, width, x=2.0, y0=2.0, y1=8.0):
    ts.call(SetPen, '/turtle1/set_pen', off=1)
    ts.call(TeleportAbsolute, '/turtle1/teleport_absolute', x=x, y=y0, theta=0.0)
    ts.latest_pose()
    ts.call(SetPen, '/turtle1/set_pen', r=rgb_pen[0], g=rgb_pen[1], b=rgb_pen[2], width=width)
    ts.call(TeleportAbsolute, '/turtle1/teleport_absolute', x=x, y=y1, theta=0.0)
    ts.latest_pose()


def row(y: float) -> int:
    return round((W - y) * 45)


def test_pen_colour_and_width_on_saved_png(ts):
    draw_vertical_line(ts, (255, 0, 0), 5)
    image = ts.canvas()
    assert (image.width(), image.height()) == (500, 500)
    assert rgb(image, 90, row(5.0)) == (255, 0, 0)
    assert rgb(image, 92, row(5.0)) == (255, 0, 0)  # width 5: two pixels either side
    assert rgb(image, 88, row(5.0)) == (255, 0, 0)
    assert rgb(image, 94, row(5.0)) == BACKGROUND
    assert rgb(image, 400, 40) == BACKGROUND


def test_width_zero_draws_one_pixel_and_off_draws_nothing(ts):
    draw_vertical_line(ts, (0, 255, 0), 0, x=3.0)
    ts.call(SetPen, '/turtle1/set_pen', off=1)
    ts.call(TeleportAbsolute, '/turtle1/teleport_absolute', x=8.0, y=5.0, theta=0.0)
    ts.latest_pose()
    image = ts.canvas()
    assert rgb(image, 135, row(5.0)) == (0, 255, 0)
    assert rgb(image, 136, row(5.0)) == BACKGROUND
    assert rgb(image, 134, row(5.0)) == BACKGROUND
    assert rgb(image, 200, row(5.0)) == BACKGROUND  # the pen-off teleport left no line


def test_default_pen_draws_the_path_of_cmd_vel(ts):
    poses = ts.collect(Pose, '/turtle1/pose')
    twist = Twist()
    twist.linear.x = 2.0
    ts.publish('/turtle1/cmd_vel', twist)
    ts.probe.spin_until(lambda: poses and poses[-1].x > CENTER + 1.5, 3, 'motion')
    image = ts.canvas()
    assert rgb(image, round((CENTER + 0.8) * 45), row(CENTER)) == PEN


def test_color_sensor_under_a_drawn_line(ts):
    draw_vertical_line(ts, (10, 200, 30), 5)
    ts.call(SetPen, '/turtle1/set_pen', off=1)
    ts.call(TeleportAbsolute, '/turtle1/teleport_absolute', x=2.0, y=5.0, theta=0.0)
    colors = ts.collect(Color, '/turtle1/color_sensor')
    ts.probe.spin_for(0.2)
    ts.probe.spin_until(lambda: colors, 5, 'color_sensor')
    assert (colors[-1].r, colors[-1].g, colors[-1].b) == (10, 200, 30)


def test_clear_erases_paths_but_keeps_turtles(ts):
    draw_vertical_line(ts, (255, 0, 0), 5)
    ts.call(Empty, '/clear')
    ts.wait_for_log(r'\[INFO\] \[\d+\.\d+\] \[turtlesim\]: Clearing turtlesim\.$')
    assert rgb(ts.canvas(), 90, row(5.0)) == BACKGROUND
    pose = ts.latest_pose()
    assert (pose.x, pose.y) == pytest.approx((2.0, 8.0))


def test_background_parameter_repaints_under_existing_drawing(ts):
    draw_vertical_line(ts, (255, 0, 0), 5)
    assert ts.set_parameter('background_r', int_value(10)).successful
    image = ts.canvas()
    assert rgb(image, 400, 40) == (10, 86, 255)
    assert rgb(image, 90, row(5.0)) == (255, 0, 0)


def test_sprite_is_drawn_at_the_turtle(ts):
    image = ts.canvas()
    centre = round(CENTER * 45)
    around = {rgb(image, centre + dx, centre + dy) for dx in range(-10, 11, 5)
              for dy in range(-10, 11, 5)}
    assert around - {BACKGROUND}, 'no turtle drawn at the centre'
    assert rgb(image, centre, centre + 40) == BACKGROUND


# ---------------------------------------------------------------------------- spawn/kill/reset


def test_spawn_auto_names_skip_taken_names(ts):
    assert ts.call(Spawn, '/spawn', x=1.0, y=2.0, theta=0.5).name == 'turtle2'
    ts.wait_for_log(r'\[turtlesim\]: Spawning turtle \[turtle2\] at x=\[1\.000000\], '
                    r'y=\[2\.000000\], theta=\[0\.500000\]')
    assert ts.call(Spawn, '/spawn', x=1.0, y=1.0, theta=0.0, name='turtle3').name == 'turtle3'
    assert ts.call(Spawn, '/spawn', x=1.0, y=1.0, theta=0.0).name == 'turtle4'
    pose = ts.latest_pose('turtle2')
    assert (pose.x, pose.y, pose.theta) == pytest.approx((1.0, 2.0, 0.5))


def test_spawn_name_clash_replies_empty_name(ts):
    assert ts.call(Spawn, '/spawn', x=1.0, y=1.0, theta=0.0, name='turtle1').name == ''
    ts.wait_for_log(r'^\[ERROR\] \[\d+\.\d+\] \[turtlesim\]: A turtle named \[turtle1\] '
                    r'already exists$')


def test_kill_removes_interfaces_and_unknown_kill_logs_error(ts):
    assert ts.call(Spawn, '/spawn', x=1.0, y=1.0, theta=0.0, name='doomed').name == 'doomed'
    client = ts.probe.node.create_client(SetPen, '/doomed/set_pen')
    assert client.wait_for_service(timeout_sec=5)
    ts.call(Kill, '/kill', name='doomed')
    deadline = time.monotonic() + 5
    while client.service_is_ready() and time.monotonic() < deadline:
        ts.probe.spin_for(0.1)
    assert not client.service_is_ready()
    ts.probe.node.destroy_client(client)
    ts.call(Kill, '/kill', name='doomed')
    ts.wait_for_log(r'^\[ERROR\] \[\d+\.\d+\] \[turtlesim\]: Tried to kill turtle \[doomed\], '
                    r'which does not exist$')


def test_killed_turtle1_is_not_auto_recreated_and_reset_restores_it(ts):
    ts.call(Kill, '/kill', name='turtle1')
    assert ts.call(Spawn, '/spawn', x=1.0, y=1.0, theta=0.0).name == 'turtle2'
    ts.call(Empty, '/reset')
    assert ts.call(Spawn, '/spawn', x=1.0, y=1.0, theta=0.0).name == 'turtle2'
    pose = ts.latest_pose('turtle1')
    assert (pose.x, pose.y) == (CENTER, CENTER)


def test_reset_moves_turtle1_home_and_clears(ts):
    draw_vertical_line(ts, (255, 0, 0), 5)
    ts.mark = len(ts.process.output)
    ts.call(Empty, '/reset')
    ts.wait_for_log(r'Resetting turtlesim\.\n.*Spawning turtle \[turtle1\] at x=\[5\.544445\]')
    pose = ts.latest_pose()
    assert (pose.x, pose.y, pose.theta) == (CENTER, CENTER, 0.0)
    assert rgb(ts.canvas(), 90, row(5.0)) == BACKGROUND
