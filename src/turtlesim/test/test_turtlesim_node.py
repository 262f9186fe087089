"""turtlesim_node as a real process over DDS: topics, services, action, parameters, canvas.

One turtlesim serves the whole module (start-up and discovery cost seconds); every test starts
from /reset, /clear and default parameters, and reads only the log written after its start.
"""

from __future__ import annotations

import math
import re
import time

import pytest
from geometry_msgs.msg import Twist
from PySide6.QtGui import QImage
from rcl_interfaces.msg import Parameter, ParameterType, ParameterValue
from rcl_interfaces.srv import DescribeParameters, GetParameters, SetParameters
from rclpy.action import ActionClient
from service_msgs.msg import ServiceEventInfo
from std_srvs.srv import Empty, Trigger
from turtlesim.action import RotateAbsolute
from turtlesim.msg import Color, Pose
from turtlesim.srv import Kill, SetPen, Spawn, TeleportAbsolute, TeleportRelative

from ws_testing import (
    RosProcess,
    TestNode,
    executable,
    leased_domain,
    ros_environment,
    turtle_qos,
)

W = 11.088889122009277
CENTER = 5.544444561004639
BACKGROUND = (69, 86, 255)
PEN = (179, 184, 255)


class Sim:
    """The module's turtlesim process, an rclpy probe on its domain, and log bookkeeping."""

    def __init__(self, process: RosProcess, probe: TestNode, png) -> None:
        self.process = process
        self.probe = probe
        self.png = png
        self.mark = 0
        self._publishers = {}
        self._subscriptions = []

    # logs -----------------------------------------------------------------------------
    def new_output(self) -> str:
        return self.process.output[self.mark:]

    def wait_for_log(self, pattern: str, timeout: float = 5.0) -> re.Match[str]:
        deadline = time.monotonic() + timeout
        while True:
            match = re.search(pattern, self.new_output(), re.MULTILINE)
            if match:
                return match
            if time.monotonic() > deadline:
                raise AssertionError(f'{pattern!r} not logged; new output:\n{self.new_output()}')
            self.probe.spin_for(0.05)

    # ROS ---------------------------------------------------------------------------------
    def call(self, srv_type, service: str, **fields):
        return self.probe.call(srv_type, service, srv_type.Request(**fields))

    def collect(self, msg_type, topic: str, qos=None) -> list:
        received: list = []
        sub = self.probe.node.create_subscription(
            msg_type, topic, received.append, turtle_qos() if qos is None else qos)
        self._subscriptions.append(sub)
        return received

    def publish(self, topic: str, msg) -> None:
        if topic not in self._publishers:
            publisher = self.probe.node.create_publisher(type(msg), topic, turtle_qos())
            self._publishers[topic] = publisher
            self.probe.spin_until(lambda: publisher.get_subscription_count() > 0, 10,
                                  f'a subscriber on {topic}')
        self._publishers[topic].publish(msg)

    def latest_pose(self, turtle: str = 'turtle1', after: float = 0.1) -> Pose:
        """A pose published at least `after` seconds from now (so queued teleports applied)."""
        poses = self.collect(Pose, f'/{turtle}/pose')
        self.probe.spin_for(after)
        self.probe.spin_until(lambda: poses, 5, f'a pose of {turtle}')
        return poses[-1]

    def set_parameter(self, name: str, value: ParameterValue):
        return self.probe.call(SetParameters, '/turtlesim/set_parameters', SetParameters.Request(
            parameters=[Parameter(name=name, value=value)])).results[0]

    def canvas(self) -> QImage:
        response = self.call(Trigger, '/turtlesim/_save_canvas')
        assert response.success, response.message
        assert response.message == str(self.png)
        image = QImage(response.message)
        assert not image.isNull()
        return image

    def cleanup(self) -> None:
        for sub in self._subscriptions:
            self.probe.node.destroy_subscription(sub)
        self._subscriptions.clear()


def rgb(image: QImage, x: int, y: int) -> tuple[int, int, int]:
    color = image.pixelColor(x, y)
    return color.red(), color.green(), color.blue()


def int_value(value: int) -> ParameterValue:
    return ParameterValue(type=ParameterType.PARAMETER_INTEGER, integer_value=value)


@pytest.fixture(scope='module')
def module_sim(tmp_path_factory):
    tmp = tmp_path_factory.mktemp('turtlesim')
    with leased_domain() as domain:
        process = RosProcess(
            [executable('turtlesim', 'turtlesim_node'), '--headless',
             '--canvas-png', str(tmp / 'c.png'), '--service-introspection', 'metadata'],
            ros_environment(domain), tmp / 'turtlesim.log')
        probe = TestNode(domain)
        try:
            process.wait_for_output(r'Spawning turtle \[turtle1\]')
            yield Sim(process, probe, tmp / 'c.png')
        finally:
            probe.close()
            assert process.stop() == 0, process.output
            assert 'Traceback' not in process.output, process.output


@pytest.fixture
def ts(module_sim):
    """The module's turtlesim, reset to its start state for this test."""
    module_sim.mark = len(module_sim.process.output)
    module_sim.call(Empty, '/reset')
    for name, value in zip(('background_r', 'background_g', 'background_b'), BACKGROUND,
                           strict=True):
        assert module_sim.set_parameter(name, int_value(value)).successful
    module_sim.set_parameter('holonomic', ParameterValue(
        type=ParameterType.PARAMETER_BOOL, bool_value=False))
    module_sim.wait_for_log(r'Resetting turtlesim\.')
    yield module_sim
    module_sim.cleanup()
    assert module_sim.process.popen.poll() is None, module_sim.new_output()


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


# ---------------------------------------------------------------------------- bad input


@pytest.mark.parametrize('fields, field', [
    ({'x': math.nan, 'y': 1.0}, 'x'),
    ({'x': 1.0, 'y': math.inf}, 'y'),
    ({'x': 1.0, 'y': 1.0, 'theta': -math.inf}, 'theta'),
])
def test_spawn_refuses_non_finite_numbers(ts, fields, field):
    assert ts.call(Spawn, '/spawn', **fields).name == ''
    ts.wait_for_log(rf'^\[ERROR\] .*Refusing to spawn: {field}=-?(nan|inf) is not allowed '
                    r'\(allowed: finite numbers\)$')
    assert ts.call(Spawn, '/spawn', x=1.0, y=1.0).name == 'turtle2'  # counter untouched


@pytest.mark.parametrize('name', ['1abc', 'has space', 'a__b', '/abs', 'x/', 'sémi', '~tilde'])
def test_spawn_refuses_invalid_names(ts, name):
    assert ts.call(Spawn, '/spawn', x=1.0, y=1.0, name=name).name == ''
    ts.wait_for_log(r'^\[ERROR\] .*Refusing to spawn: name=.* is not a valid ROS name '
                    r'\(allowed: ')
    assert ts.call(Spawn, '/spawn', x=1.0, y=1.0).name == 'turtle2'


def test_spawn_accepts_nested_names(ts):
    assert ts.call(Spawn, '/spawn', x=1.0, y=1.0, name='team/leader').name == 'team/leader'
    assert ts.latest_pose('team/leader').x == pytest.approx(1.0)


@pytest.mark.parametrize('service, srv_type, fields, field', [
    ('teleport_absolute', TeleportAbsolute, {'x': math.nan}, 'x'),
    ('teleport_absolute', TeleportAbsolute, {'theta': math.inf}, 'theta'),
    ('teleport_relative', TeleportRelative, {'linear': math.nan}, 'linear'),
    ('teleport_relative', TeleportRelative, {'angular': -math.inf}, 'angular'),
])
def test_teleports_refuse_non_finite_numbers(ts, service, srv_type, fields, field):
    ts.call(srv_type, f'/turtle1/{service}', **fields)
    ts.wait_for_log(rf'^\[ERROR\] .*Refusing turtle1/{service}: {field}=-?(nan|inf) is not '
                    r'allowed \(allowed: finite numbers\)$')
    pose = ts.latest_pose()
    assert (pose.x, pose.y, pose.theta) == (CENTER, CENTER, 0.0)


@pytest.mark.parametrize('field, value', [
    ('linear.x', math.nan), ('angular.z', math.inf), ('linear.y', -math.inf), ('linear.x', 1e39),
])
def test_cmd_vel_refuses_non_finite_numbers(ts, field, value):
    twist = Twist()
    part, axis = field.split('.')
    setattr(getattr(twist, part), axis, value)
    ts.publish('/turtle1/cmd_vel', twist)
    ts.wait_for_log(rf'^\[ERROR\] .*Ignoring turtle1/cmd_vel: {re.escape(field)}=\S+ is not '
                    r'allowed \(allowed: finite values')
    pose = ts.latest_pose()
    assert (pose.x, pose.y, pose.theta) == (CENTER, CENTER, 0.0)


def test_huge_but_finite_speed_only_hits_the_wall(ts):
    twist = Twist()
    twist.linear.x = 1e30
    ts.publish('/turtle1/cmd_vel', twist)
    ts.wait_for_log(r'Oh no! I hit the wall!')
    pose = ts.latest_pose()
    assert pose.x == pytest.approx(W)
    assert pose.linear_velocity == pytest.approx(1e30, rel=1e-6)


# ---------------------------------------------------------------------------- parameters


def test_parameters_have_ranges_and_descriptions(ts):
    names = ['background_r', 'background_g', 'background_b', 'holonomic']
    values = ts.probe.call(GetParameters, '/turtlesim/get_parameters',
                           GetParameters.Request(names=names)).values
    assert [v.integer_value for v in values[:3]] == list(BACKGROUND)
    assert values[3].type == ParameterType.PARAMETER_BOOL and values[3].bool_value is False
    descriptors = ts.probe.call(DescribeParameters, '/turtlesim/describe_parameters',
                                DescribeParameters.Request(names=names)).descriptors
    assert descriptors[0].description == 'Red channel of the background color'
    assert descriptors[1].description == 'Green channel of the background color'
    assert descriptors[2].description == 'Blue channel of the background color'
    assert descriptors[3].description == 'If true, then turtles will be holonomic'
    for descriptor in descriptors[:3]:
        (rng,) = descriptor.integer_range
        assert (rng.from_value, rng.to_value, rng.step) == (0, 255, 1)


@pytest.mark.parametrize('name, value, reason', [
    ('background_r', int_value(256), 'background_r must be an integer in 0..255, got 256'),
    ('background_g', int_value(-1), 'background_g must be an integer in 0..255, got -1'),
    ('background_b', ParameterValue(type=ParameterType.PARAMETER_STRING, string_value='red'),
     "background_b must be an integer in 0..255, got string 'red'"),
    ('background_r', ParameterValue(type=ParameterType.PARAMETER_DOUBLE, double_value=1.0),
     'background_r must be an integer in 0..255, got double 1.0'),
    ('holonomic', int_value(1), 'holonomic must be a bool (true or false), got integer 1'),
])
def test_bad_parameter_values_are_refused(ts, name, value, reason):
    result = ts.set_parameter(name, value)
    assert not result.successful
    assert reason in result.reason
    ts.wait_for_log(rf'^\[ERROR\] .*Refusing to set parameter {re.escape(reason)}')
    values = ts.probe.call(GetParameters, '/turtlesim/get_parameters',
                           GetParameters.Request(names=['background_r', 'background_g',
                                                        'background_b'])).values
    assert [v.integer_value for v in values] == list(BACKGROUND)
    assert rgb(ts.canvas(), 400, 40) == BACKGROUND


# ---------------------------------------------------------------------------- action


class Rotation:
    def __init__(self, ts, theta: float) -> None:
        self.ts = ts
        self.client = ActionClient(ts.probe.node, RotateAbsolute, '/turtle1/rotate_absolute')
        assert self.client.wait_for_server(timeout_sec=10)
        self.feedback: list[float] = []
        future = self.client.send_goal_async(
            RotateAbsolute.Goal(theta=theta),
            feedback_callback=lambda msg: self.feedback.append(msg.feedback.remaining))
        ts.probe.spin_until(future.done, 5, 'the goal response')
        self.handle = future.result()
        self.result_future = self.handle.get_result_async() if self.handle.accepted else None

    def result(self, timeout: float = 10.0):
        self.ts.probe.spin_until(self.result_future.done, timeout, 'the rotation result')
        return self.result_future.result()

    def destroy(self) -> None:
        self.client.destroy()


def test_rotate_absolute_succeeds_with_feedback_and_delta(ts):
    from action_msgs.msg import GoalStatus
    rotation = Rotation(ts, 1.0)
    assert rotation.handle.accepted
    outcome = rotation.result()
    assert outcome.status == GoalStatus.STATUS_SUCCEEDED
    assert outcome.result.delta == pytest.approx(-1.0, abs=0.03)
    assert len(rotation.feedback) > 30  # ~1 s of feedback at the tick rate
    assert rotation.feedback[0] == pytest.approx(1.0, abs=0.05)
    assert abs(rotation.feedback[-1]) < 0.05
    ts.wait_for_log(r'\[INFO\] .*\[turtlesim\]: Rotation goal completed successfully$')
    pose = ts.latest_pose()
    assert abs(pose.theta - 1.0) < 0.02
    assert pose.angular_velocity == 0.0
    rotation.destroy()


def test_rotate_absolute_goes_the_short_way_at_one_rad_per_second(ts):
    ts.call(TeleportAbsolute, '/turtle1/teleport_absolute', x=CENTER, y=CENTER, theta=3.0)
    ts.latest_pose()
    poses = ts.collect(Pose, '/turtle1/pose')
    rotation = Rotation(ts, -3.0)
    ts.probe.spin_until(lambda: poses and poses[-1].angular_velocity != 0.0, 2, 'turning')
    assert poses[-1].angular_velocity == 1.0
    rotation.result()
    rotation.destroy()


def test_new_goal_aborts_the_previous_one(ts):
    from action_msgs.msg import GoalStatus
    first = Rotation(ts, 3.0)
    ts.probe.spin_for(0.2)
    second = Rotation(ts, -0.5)
    assert first.result().status == GoalStatus.STATUS_ABORTED
    ts.wait_for_log(r'\[WARN\] .*\[turtlesim\]: Rotation goal received before a previous goal '
                    r'finished\. Aborting previous goal$')
    assert second.result().status == GoalStatus.STATUS_SUCCEEDED
    first.destroy()
    second.destroy()


def test_cmd_vel_aborts_rotation(ts):
    from action_msgs.msg import GoalStatus
    rotation = Rotation(ts, 3.0)
    ts.probe.spin_for(0.2)
    twist = Twist()
    twist.angular.z = -0.3
    ts.publish('/turtle1/cmd_vel', twist)
    assert rotation.result().status == GoalStatus.STATUS_ABORTED
    ts.wait_for_log(r'\[WARN\] .*Velocity command received during rotation goal\. Aborting goal$')
    assert ts.latest_pose().angular_velocity == pytest.approx(-0.3)  # the new command applies
    rotation.destroy()


def test_cancel_rotation(ts):
    from action_msgs.msg import GoalStatus
    rotation = Rotation(ts, 3.0)
    ts.probe.spin_for(0.3)
    cancel = rotation.handle.cancel_goal_async()
    ts.probe.spin_until(cancel.done, 5, 'the cancel response')
    assert len(cancel.result().goals_canceling) == 1
    assert rotation.result().status == GoalStatus.STATUS_CANCELED
    ts.wait_for_log(r'\[INFO\] .*\[turtlesim\]: Rotation goal canceled$')
    pose = ts.latest_pose()
    assert pose.angular_velocity == 0.0
    assert 0.1 < pose.theta < 1.5
    rotation.destroy()


def test_non_finite_goal_is_rejected(ts):
    rotation = Rotation(ts, math.nan)
    assert not rotation.handle.accepted
    ts.wait_for_log(r'\[ERROR\] .*Rejecting turtle1/rotate_absolute goal: theta=nan is not '
                    r'allowed \(allowed: finite numbers\)')
    rotation.destroy()


# ---------------------------------------------------------------------------- introspection


def test_set_pen_calls_are_visible_through_service_introspection(ts):
    events = ts.collect(SetPen.Event, '/turtle1/set_pen/_service_event', qos=10)
    ts.probe.spin_for(0.5)  # let the event subscription match
    started = time.perf_counter()
    for width in (1, 2, 3):
        ts.call(SetPen, '/turtle1/set_pen', r=1, g=2, b=3, width=width)
    elapsed = time.perf_counter() - started
    ts.probe.spin_until(lambda: len(events) >= 6, 5, 'six service events')
    kinds = [event.info.event_type for event in events]
    assert kinds.count(ServiceEventInfo.REQUEST_RECEIVED) == 3
    assert kinds.count(ServiceEventInfo.RESPONSE_SENT) == 3
    assert elapsed < 3.0


def test_reset_and_kill_during_rotation_abort_the_goal(ts):
    from action_msgs.msg import GoalStatus
    rotation = Rotation(ts, 3.0)
    ts.probe.spin_for(0.2)
    ts.call(Empty, '/reset')
    assert rotation.result().status == GoalStatus.STATUS_ABORTED
    rotation.destroy()
    ts.probe.spin_for(0.3)
    assert ts.call(Spawn, '/spawn', x=3.0, y=3.0, name='spinner').name == 'spinner'
    client = ActionClient(ts.probe.node, RotateAbsolute, '/spinner/rotate_absolute')
    assert client.wait_for_server(timeout_sec=10)
    future = client.send_goal_async(RotateAbsolute.Goal(theta=2.0))
    ts.probe.spin_until(future.done, 5, 'the goal response')
    result = future.result().get_result_async()
    ts.probe.spin_for(0.2)
    ts.call(Kill, '/kill', name='spinner')
    ts.probe.spin_until(result.done, 5, 'the aborted result')
    assert result.result().status == GoalStatus.STATUS_ABORTED
    client.destroy()
    after_reset = Rotation(ts, 0.5)  # the new turtle1's action server works
    assert after_reset.result().status == GoalStatus.STATUS_SUCCEEDED
    after_reset.destroy()
    assert 'Traceback' not in ts.new_output()
