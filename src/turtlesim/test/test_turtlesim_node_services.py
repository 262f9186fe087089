"""turtlesim_node as a real process over DDS: bad input, parameters, the RotateAbsolute
action and service introspection.

One turtlesim serves the whole module (conftest.py); every test starts from /reset, /clear and
default parameters, and reads only the log written after its start.
"""

from __future__ import annotations

import math
import re
import time

import pytest
from geometry_msgs.msg import Twist
from headless_turtlesim import BACKGROUND, CENTER, W, int_value, rgb
from rcl_interfaces.msg import ParameterType, ParameterValue
from rcl_interfaces.srv import DescribeParameters, GetParameters
from rclpy.action import ActionClient
from service_msgs.msg import ServiceEventInfo
from std_srvs.srv import Empty
from turtlesim.action import RotateAbsolute
from turtlesim.msg import Pose
from turtlesim.srv import Kill, SetPen, Spawn, TeleportAbsolute, TeleportRelative

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
