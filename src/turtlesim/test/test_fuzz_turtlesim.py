"""Generated input for every turtlesim service, the action, cmd_vel and parameters (Hypothesis).

One headless turtlesim serves the module. Every example must be answered (or refused with an
ERROR naming the field and what is allowed), change nothing when refused, keep the node up,
and keep every published pose finite. bench/fuzz.py runs the same with 10,000 cases.
"""

from __future__ import annotations

import math
import re

import pytest
from geometry_msgs.msg import Twist
from hypothesis import given
from hypothesis import strategies as st
from rcl_interfaces.msg import Parameter, ParameterType
from rcl_interfaces.srv import GetParameters, SetParameters
from rclpy.action import ActionClient
from std_srvs.srv import Empty
from turtlesim.action import RotateAbsolute
from turtlesim.msg import Pose
from turtlesim.srv import Kill, SetPen, Spawn, TeleportAbsolute, TeleportRelative

from ws_testing import RosProcess, TestNode, executable, leased_domain, ros_environment, turtle_qos
from ws_testing.fuzz import (
    CI,
    Target,
    describe,
    floats32,
    floats64,
    names,
    parameter_values,
    uint8,
)

TOKEN = r'[A-Za-z_][A-Za-z0-9_]*'
# The longest name a turtle creates, /<name>/rotate_absolute/_action/cancel_goal, must fit
# in DDS's 247 characters.
LONGEST_NAME = 247 - len('//rotate_absolute/_action/cancel_goal')
BACKGROUND = {'background_r': 69, 'background_g': 86, 'background_b': 255}


def valid_turtle_name(name: str) -> bool:
    return (re.fullmatch(rf'{TOKEN}(/{TOKEN})*', name) is not None and '__' not in name
            and len(name) <= LONGEST_NAME)


class Sim(Target):
    def __init__(self, process: RosProcess, probe: TestNode) -> None:
        super().__init__(process, probe)
        self.poses: list[Pose] = []
        probe.node.create_subscription(Pose, '/turtle1/pose', self.poses.append, turtle_qos())
        self.cmd_vel = probe.node.create_publisher(Twist, '/turtle1/cmd_vel', turtle_qos())
        self.rotate = ActionClient(probe.node, RotateAbsolute, '/turtle1/rotate_absolute')

    def next_poses(self, count: int = 2) -> list[Pose]:
        """Wait for `count` new poses (so a queued teleport has been applied); all finite."""
        start = len(self.poses)
        self.probe.spin_until(lambda: len(self.poses) >= start + count, 10, 'new poses')
        for pose in self.poses[start:]:
            values = (pose.x, pose.y, pose.theta, pose.linear_velocity, pose.angular_velocity)
            assert all(math.isfinite(v) for v in values), pose
        del self.poses[:-1]
        return self.poses[-1:]


@pytest.fixture(scope='module')
def sim(tmp_path_factory):
    tmp = tmp_path_factory.mktemp('fuzz-turtlesim')
    with leased_domain() as domain:
        process = RosProcess([executable('turtlesim', 'turtlesim_node'), '--headless'],
                             ros_environment(domain), tmp / 'turtlesim.log')
        probe = TestNode(domain)
        try:
            process.wait_for_output(r'Spawning turtle \[turtle1\]', timeout=20)
            sim = Sim(process, probe)
            probe.spin_until(lambda: sim.poses, 20, 'the first pose of turtle1')
            yield sim
        finally:
            probe.close()
            assert process.stop() == 0, process.output[-3000:]
            assert 'Traceback' not in process.output, process.output[-3000:]
            assert not list(tmp.glob('*.png')), 'a canvas PNG was written unasked'


@pytest.fixture
def ts(sim):
    sim.call(Empty, '/reset', Empty.Request())
    sim.next_poses()
    yield sim
    sim.assert_alive()


def test_spawn_and_kill(ts):
    @CI
    @given(name=names, x=floats32, y=floats32, theta=floats32)
    def check(name, x, y, theta):
        response = ts.call(Spawn, '/spawn', Spawn.Request(name=name, x=x, y=y, theta=theta))
        bad = [f for f, v in (('x', x), ('y', y), ('theta', theta)) if not math.isfinite(v)]
        if bad:
            assert response.name == ''
            ts.wait_for_log(rf'\[ERROR\] .*Refusing to spawn: {bad[0]}=-?(nan|inf) is not '
                            r'allowed \(allowed: finite numbers\)')
        elif name and not valid_turtle_name(name):
            assert response.name == ''
            ts.wait_for_log(r'\[ERROR\] .*Refusing to spawn: name=.* is not a valid ROS name '
                            r'\(allowed: ')
        elif name == 'turtle1':
            assert response.name == ''
            ts.wait_for_log(r'A turtle named \[turtle1\] already exists')
        else:
            assert response.name == (name or response.name)
            assert re.fullmatch(r'turtle\d+', response.name) or name
            ts.call(Kill, '/kill', Kill.Request(name=response.name))
        if not response.name:
            assert 'Spawning turtle' not in ts.new_output()
        ts.next_poses(1)

    check()


def test_kill_unknown_names(ts):
    @CI
    @given(name=names.filter(lambda n: n != 'turtle1'))
    def check(name):
        ts.call(Kill, '/kill', Kill.Request(name=name))
        ts.wait_for_log(r'\[ERROR\] .*Tried to kill turtle \[.*\], which does not exist',)

    check()
    ts.next_poses(1)  # turtle1 is still there


def test_set_pen(ts):
    @CI
    @given(r=uint8, g=uint8, b=uint8, width=uint8, off=uint8)
    def check(r, g, b, width, off):
        ts.call(SetPen, '/turtle1/set_pen', SetPen.Request(r=r, g=g, b=b, width=width, off=off))

    check()
    ts.next_poses()


def test_teleports(ts):
    @CI
    @given(kind=st.sampled_from(['absolute', 'relative']), a=floats32, b=floats32, c=floats32)
    def check(kind, a, b, c):
        before = ts.next_poses()[-1]
        if kind == 'absolute':
            fields = {'x': a, 'y': b, 'theta': c}
            ts.call(TeleportAbsolute, '/turtle1/teleport_absolute',
                    TeleportAbsolute.Request(**fields))
        else:
            fields = {'linear': a, 'angular': b}
            ts.call(TeleportRelative, '/turtle1/teleport_relative',
                    TeleportRelative.Request(**fields))
        bad = [f for f, v in fields.items() if not math.isfinite(v)]
        after = ts.next_poses()[-1]
        if bad:
            ts.wait_for_log(rf'\[ERROR\] .*Refusing turtle1/teleport_{kind}: {bad[0]}=-?(nan|inf) '
                            r'is not allowed \(allowed: finite numbers\)')
            assert (after.x, after.y, after.theta) == (before.x, before.y, before.theta)
        else:
            assert 0.0 <= after.x <= 11.09 and 0.0 <= after.y <= 11.09, after

    check()


def test_cmd_vel(ts):
    @CI
    @given(lx=floats64, ly=floats64, lz=floats64, ax=floats64, ay=floats64, az=floats64)
    def check(lx, ly, lz, ax, ay, az):
        twist = Twist()
        twist.linear.x, twist.linear.y, twist.linear.z = lx, ly, lz
        twist.angular.x, twist.angular.y, twist.angular.z = ax, ay, az
        ts.cmd_vel.publish(twist)
        after = ts.next_poses()[-1]
        assert 0.0 <= after.x <= 11.09 and 0.0 <= after.y <= 11.09, after
        assert -math.pi <= after.theta <= math.pi, after
        ts.assert_alive()

    ts.probe.spin_until(lambda: ts.cmd_vel.get_subscription_count() > 0, 10, 'cmd_vel matched')
    check()


def test_rotate_absolute(ts):
    ts.rotate.wait_for_server(timeout_sec=10)

    @CI
    @given(theta=floats32)
    def check(theta):
        ts.mark = len(ts.process.output)
        future = ts.rotate.send_goal_async(RotateAbsolute.Goal(theta=theta))
        ts.probe.executor.spin_until_future_complete(future, timeout_sec=10)
        ts.assert_alive()
        assert future.done(), 'rotate_absolute goal unanswered'
        handle = future.result()
        if not math.isfinite(theta):
            assert not handle.accepted
            ts.wait_for_log(r'\[ERROR\] .*Rejecting turtle1/rotate_absolute goal: '
                            r'theta=-?(nan|inf) is not allowed \(allowed: finite numbers\)')
            return
        assert handle.accepted
        result = handle.get_result_async()
        ts.probe.executor.spin_until_future_complete(handle.cancel_goal_async(), timeout_sec=10)
        ts.probe.executor.spin_until_future_complete(result, timeout_sec=10)
        assert result.done(), 'rotate_absolute result unanswered'
        assert math.isfinite(result.result().result.delta)
        ts.next_poses()

    check()


def test_parameters(ts):
    get = GetParameters.Request(names=[*BACKGROUND, 'holonomic'])

    @CI
    @given(name=st.one_of(st.sampled_from([*BACKGROUND, 'holonomic']), names),
           value=parameter_values())
    def check(name, value):
        before = ts.call(GetParameters, '/turtlesim/get_parameters', get).values
        result = ts.call(SetParameters, '/turtlesim/set_parameters', SetParameters.Request(
            parameters=[Parameter(name=name, value=value)])).results[0]
        kind, given_value = describe(value)
        if name in BACKGROUND:
            allowed = kind == ParameterType.PARAMETER_INTEGER and 0 <= given_value <= 255
        elif name == 'holonomic':
            allowed = kind == ParameterType.PARAMETER_BOOL
        else:
            allowed = False
        assert result.successful == allowed, (name, value, result)
        after = ts.call(GetParameters, '/turtlesim/get_parameters', get).values
        if not allowed:
            assert result.reason
            assert repr(name) in result.reason or name in result.reason, result.reason
            assert [describe(v) for v in after] == [describe(v) for v in before]
        elif name in BACKGROUND or name == 'holonomic':
            index = [*BACKGROUND, 'holonomic'].index(name)
            assert describe(after[index]) == (kind, given_value)

    try:
        check()
    finally:
        ts.call(SetParameters, '/turtlesim/set_parameters', SetParameters.Request(parameters=[
            Parameter(name=n, value=parameter_value_int(v)) for n, v in BACKGROUND.items()]))


def parameter_value_int(value: int):
    from rcl_interfaces.msg import ParameterValue
    return ParameterValue(type=ParameterType.PARAMETER_INTEGER, integer_value=value)
