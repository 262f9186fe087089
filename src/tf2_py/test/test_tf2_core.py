"""tf2's core (tf2_py.BufferCore) against the cases of upstream geometry2's own tests:
cache interpolation (cartesian and angular), re-parenting, extrapolation messages, chains,
static/dynamic mixes, time 0, time travel through a fixed frame, and bad input.

Same inputs and expected outputs as geometry2's cache_unittest.cpp, simple_tf2_core.cpp and
tf2_py/test/test_buffer_core.py; the code is ours. In-process: this is the maths and the
bookkeeping, the ROS side is in test_tf2_tools.py and test_turtle_tf2.py.
"""
from __future__ import annotations

import math

import pytest
import rclpy.duration
import rclpy.time
from geometry_msgs.msg import TransformStamped
from tf2_py import (
    BufferCore,
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
)
from tf2_py.maths import euler_from_quaternion, quaternion_from_euler

LATEST = rclpy.time.Time()


def at(seconds: float) -> rclpy.time.Time:
    return rclpy.time.Time(nanoseconds=round(seconds * 1e9))


def stamped(parent: str, child: str, seconds: float, xyz=(0.0, 0.0, 0.0),
            rpy=(0.0, 0.0, 0.0), quaternion=None) -> TransformStamped:
    t = TransformStamped()
    t.header.frame_id, t.child_frame_id = parent, child
    t.header.stamp = at(seconds).to_msg()
    t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = xyz
    q = quaternion or quaternion_from_euler(*rpy)
    r = t.transform.rotation
    r.x, r.y, r.z, r.w = (float(v) for v in q)
    return t


def xyz(t: TransformStamped) -> tuple[float, float, float]:
    v = t.transform.translation
    return v.x, v.y, v.z


def yaw(t: TransformStamped) -> float:
    q = t.transform.rotation
    return euler_from_quaternion((q.x, q.y, q.z, q.w))[2]


def test_cartesian_interpolation_is_linear_between_two_samples() -> None:
    buffer = BufferCore()
    buffer.set_transform(stamped('parent', 'child', 1.0, (1.0, 2.0, 3.0)), 'test')
    buffer.set_transform(stamped('parent', 'child', 2.0, (3.0, 6.0, -3.0)), 'test')
    for fraction in (0.0, 0.25, 0.5, 0.9, 1.0):
        result = buffer.lookup_transform_core('parent', 'child', at(1.0 + fraction))
        assert xyz(result) == pytest.approx((1.0 + 2 * fraction, 2.0 + 4 * fraction,
                                             3.0 - 6 * fraction))
        assert result.header.stamp == at(1.0 + fraction).to_msg()
        assert (result.header.frame_id, result.child_frame_id) == ('parent', 'child')


def test_angular_interpolation_is_slerp_along_the_shortest_way() -> None:
    buffer = BufferCore()
    buffer.set_transform(stamped('parent', 'child', 1.0, rpy=(0.0, 0.0, 0.0)), 'test')
    buffer.set_transform(stamped('parent', 'child', 2.0, rpy=(0.0, 0.0, math.pi / 2)), 'test')
    assert yaw(buffer.lookup_transform_core('parent', 'child', at(1.5))) == pytest.approx(
        math.pi / 4)
    # 170 deg to -170 deg goes through 180, not through 0.
    buffer.set_transform(stamped('parent', 'wrap', 1.0, rpy=(0.0, 0.0, math.radians(170))), 't')
    buffer.set_transform(stamped('parent', 'wrap', 2.0, rpy=(0.0, 0.0, math.radians(-170))), 't')
    assert abs(yaw(buffer.lookup_transform_core('parent', 'wrap', at(1.5)))) == pytest.approx(
        math.pi)


def test_no_interpolation_across_a_change_of_parent() -> None:
    buffer = BufferCore()
    buffer.set_transform(stamped('a', 'child', 1.0, (1.0, 0.0, 0.0)), 'test')
    buffer.set_transform(stamped('b', 'child', 2.0, (5.0, 0.0, 0.0)), 'test')
    buffer.set_transform(stamped('root', 'a', 1.0), 'test')
    buffer.set_transform(stamped('root', 'a', 2.0), 'test')
    buffer.set_transform(stamped('root', 'b', 1.0, (0.0, 10.0, 0.0)), 'test')
    buffer.set_transform(stamped('root', 'b', 2.0, (0.0, 10.0, 0.0)), 'test')
    # Between the samples the older one holds, with its parent a.
    assert xyz(buffer.lookup_transform_core('root', 'child', at(1.5))) == (1.0, 0.0, 0.0)
    assert xyz(buffer.lookup_transform_core('root', 'child', at(2.0))) == (5.0, 10.0, 0.0)


def test_extrapolation_messages_as_tf2() -> None:
    buffer = BufferCore()
    buffer.set_transform(stamped('parent', 'child', 10.0), 'test')
    with pytest.raises(ExtrapolationException) as single:
        buffer.lookup_transform_core('parent', 'child', at(11.0))
    assert str(single.value) == (
        'Lookup would require extrapolation at time 11.000000, but only time 10.000000 is in '
        'the buffer, when looking up transform from frame [child] to frame [parent]')
    buffer.set_transform(stamped('parent', 'child', 12.0), 'test')
    with pytest.raises(ExtrapolationException) as future:
        buffer.lookup_transform_core('parent', 'child', at(12.5))
    assert str(future.value) == (
        'Lookup would require extrapolation into the future.  Requested time 12.500000 but '
        'the latest data is at time 12.000000, when looking up transform from frame [child] '
        'to frame [parent]')
    with pytest.raises(ExtrapolationException) as past:
        buffer.lookup_transform_core('child', 'parent', at(9.0))
    assert str(past.value) == (
        'Lookup would require extrapolation into the past.  Requested time 9.000000 but the '
        'earliest data is at time 10.000000, when looking up transform from frame [parent] '
        'to frame [child]')
    ok, why = buffer.can_transform_core('parent', 'child', at(12.5))
    assert (ok, 'extrapolation into the future' in why) == (False, True)


def test_chains_up_down_and_across_the_tree() -> None:
    #        world
    #       /     \
    #     a(+x1)   b(+y1, yaw 90)
    #     |         |
    #     c(+x1)    d(+x1)
    buffer = BufferCore()
    for seconds in (1.0, 2.0):
        buffer.set_transform(stamped('world', 'a', seconds, (1.0, 0.0, 0.0)), 'test')
        buffer.set_transform(stamped('a', 'c', seconds, (1.0, 0.0, 0.0)), 'test')
        buffer.set_transform(stamped('world', 'b', seconds, (0.0, 1.0, 0.0),
                                     rpy=(0.0, 0.0, math.pi / 2)), 'test')
        buffer.set_transform(stamped('b', 'd', seconds, (1.0, 0.0, 0.0)), 'test')
    assert xyz(buffer.lookup_transform_core('world', 'c', LATEST)) == pytest.approx((2, 0, 0))
    assert xyz(buffer.lookup_transform_core('c', 'world', LATEST)) == pytest.approx((-2, 0, 0))
    # d is 1 m along b's x, which points along world's y.
    assert xyz(buffer.lookup_transform_core('world', 'd', LATEST)) == pytest.approx((0, 2, 0))
    across = buffer.lookup_transform_core('c', 'd', at(1.5))
    assert xyz(across) == pytest.approx((-2.0, 2.0, 0.0))
    assert yaw(across) == pytest.approx(math.pi / 2)
    # c is 2 m along world x and 2 m back along world y from d; d's x points along world y.
    assert xyz(buffer.lookup_transform_core('d', 'c', at(1.5))) == pytest.approx((-2, -2, 0))
    assert xyz(buffer.lookup_transform_core('a', 'a', LATEST)) == (0.0, 0.0, 0.0)


def test_time_zero_is_the_latest_time_common_to_the_chain() -> None:
    buffer = BufferCore()
    buffer.set_transform(stamped('world', 'a', 1.0), 'test')
    buffer.set_transform(stamped('world', 'a', 3.0), 'test')
    buffer.set_transform(stamped('a', 'b', 1.0), 'test')
    buffer.set_transform(stamped('a', 'b', 2.0), 'test')
    assert buffer.get_latest_common_time('world', 'b') == at(2.0)
    assert buffer.lookup_transform_core('world', 'b', LATEST).header.stamp == at(2.0).to_msg()
    # A static frame has no time of its own: it does not hold the common time back.
    buffer.set_transform_static(stamped('b', 'sensor', 0.0, (0.0, 0.0, 1.0)), 'test')
    latest = buffer.lookup_transform_core('world', 'sensor', LATEST)
    assert latest.header.stamp == at(2.0).to_msg()
    assert xyz(latest) == (0.0, 0.0, 1.0)
    # and a static frame answers at any time, even far past the dynamic ones.
    assert xyz(buffer.lookup_transform_core('b', 'sensor', at(1000.0))) == (0.0, 0.0, 1.0)


def test_static_frames_survive_clear_and_dynamic_ones_do_not() -> None:
    buffer = BufferCore()
    buffer.set_transform_static(stamped('base', 'laser', 0.0, (0.5, 0.0, 0.0)), 'test')
    buffer.set_transform(stamped('odom', 'base', 1.0), 'test')
    buffer.clear()
    assert buffer.can_transform_core('base', 'laser', LATEST) == (True, '')
    assert buffer.can_transform_core('odom', 'base', LATEST)[0] is False


def test_time_travel_through_a_fixed_frame() -> None:
    """The "Traveling in time" page: where was carrot 5 s ago, seen from turtle2 now."""
    buffer = BufferCore()
    for seconds in range(0, 11):
        # turtle2 drives along x at 1 m/s; carrot stands still at (5, 5) until t=7, then jumps.
        buffer.set_transform(stamped('world', 'turtle2', seconds, (float(seconds), 0.0, 0.0)), 't')
        carrot = (5.0, 5.0, 0.0) if seconds < 7 else (0.0, 9.0, 0.0)
        buffer.set_transform(stamped('world', 'carrot', seconds, carrot), 't')
    full = buffer.lookup_transform_full_core('turtle2', at(10.0), 'carrot', at(5.0), 'world')
    assert xyz(full) == pytest.approx((5.0 - 10.0, 5.0, 0.0))
    assert full.header.stamp == at(10.0).to_msg()
    # Without the fixed frame both are taken at the past time: a different answer.
    past = buffer.lookup_transform_core('turtle2', 'carrot', at(5.0))
    assert xyz(past) == pytest.approx((0.0, 5.0, 0.0))
    assert buffer.can_transform_full_core('turtle2', at(10.0), 'carrot', at(5.0), 'world') == (
        True, '')


def test_frames_in_two_trees_and_unknown_or_invalid_frames() -> None:
    buffer = BufferCore()
    buffer.set_transform(stamped('map', 'a', 1.0), 'test')
    buffer.set_transform(stamped('odom', 'b', 1.0), 'test')
    with pytest.raises(ConnectivityException) as unconnected:
        buffer.lookup_transform_core('a', 'b', LATEST)
    assert str(unconnected.value) == (
        "Could not find a connection between 'a' and 'b' because they are not part of the "
        'same tree.Tf has two or more unconnected trees.')
    with pytest.raises(LookupException) as unknown:
        buffer.lookup_transform_core('turtle2', 'a', LATEST)
    assert str(unknown.value) == ('"turtle2" passed to lookupTransform argument target_frame '
                                  'does not exist. ')
    with pytest.raises(InvalidArgumentException) as empty:
        buffer.lookup_transform_core('a', '', LATEST)
    assert str(empty.value) == ('Invalid argument "" passed to lookupTransform argument '
                                'source_frame - in tf2 frame_ids cannot be empty')
    with pytest.raises(InvalidArgumentException) as slash:
        buffer.lookup_transform_core('/map', 'a', LATEST)
    assert "cannot start with a '/'" in str(slash.value)
    assert buffer.can_transform_core('a', 'nowhere', LATEST) == (
        False, 'Invalid frame ID "nowhere" passed to canTransform argument source_frame - '
        'frame does not exist')


def test_a_loop_is_reported_not_followed_forever() -> None:
    buffer = BufferCore()
    buffer.set_transform(stamped('a', 'b', 1.0), 'test')
    buffer.set_transform(stamped('b', 'c', 1.0), 'test')
    buffer.set_transform(stamped('c', 'a', 1.0), 'test')
    buffer.set_transform(stamped('x', 'y', 1.0), 'test')
    with pytest.raises(LookupException) as loop:
        buffer.lookup_transform_core('x', 'a', at(1.0))
    assert str(loop.value).startswith('The tf tree is invalid because it contains a loop.\n'
                                      'Frame b exists with parent a.\n')


def test_bad_input_is_refused_and_changes_nothing(capfd) -> None:
    buffer = BufferCore()
    buffer.set_transform(stamped('parent', 'child', 1.0, (1.0, 0.0, 0.0)), 'good')
    bad = [stamped('parent', 'child', 2.0, (math.nan, 0.0, 0.0)),
           stamped('parent', 'child', 2.0, quaternion=(0.0, 0.0, 0.0, 2.0)),
           stamped('parent', 'parent', 2.0),
           stamped('', 'child', 2.0),
           stamped('parent', '', 2.0)]
    for transform in bad:
        assert buffer.set_transform(transform, 'fuzzer') is None  # as upstream: logged, not told
    logged = capfd.readouterr().err.splitlines()
    assert [line.split(']: ')[1].split(':')[0] for line in logged] == [
        'TF_NAN_INPUT', 'TF_DENORMALIZED_QUATERNION', 'TF_SELF_TRANSFORM', 'TF_NO_FRAME_ID',
        'TF_NO_CHILD_FRAME_ID']
    assert logged[1].startswith('[ERROR] [')
    assert logged[1].endswith(
        ']: TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id "child" from '
        'authority "fuzzer" because of an invalid quaternion in the transform (0.000000 '
        '0.000000 0.000000 2.000000)')
    # Nothing changed: one frame, its one sample.
    assert buffer.lookup_transform_core('parent', 'child', LATEST).header.stamp == at(1).to_msg()
    assert buffer._getFrameStrings() == ['child', 'parent']


def test_cache_keeps_its_cache_time_and_refuses_older_data(capfd) -> None:
    buffer = BufferCore(rclpy.duration.Duration(seconds=10))
    for seconds in range(0, 31):
        buffer.set_transform(stamped('parent', 'child', seconds), 'test')
    # Pruned before each insert, against the newest stamp so far (29 s): 19 s is kept.
    with pytest.raises(ExtrapolationException, match=r'earliest data is at time 19\.000000'):
        buffer.lookup_transform_core('parent', 'child', at(15.0))
    assert buffer.set_transform(stamped('parent', 'child', 5.0), 'late') is None
    assert 'TF_OLD_DATA ignoring data from the past for frame child at time 5.000000 ' \
           'according to authority late' in capfd.readouterr().err


def test_duplicate_and_out_of_order_samples() -> None:
    buffer = BufferCore()
    for seconds in (3.0, 1.0, 2.0, 2.0):
        buffer.set_transform(stamped('parent', 'child', seconds, (seconds, 0.0, 0.0)), 'test')
    assert xyz(buffer.lookup_transform_core('parent', 'child', at(1.5))) == (1.5, 0.0, 0.0)
    assert xyz(buffer.lookup_transform_core('parent', 'child', LATEST)) == (3.0, 0.0, 0.0)
    assert len(buffer._caches['child']) == 3


def test_all_frames_as_yaml_as_tf2_prints_it() -> None:
    buffer = BufferCore()
    for seconds in (1.0, 1.5, 2.0):
        buffer.set_transform(stamped('world', 'turtle1', seconds), 'default_authority')
    buffer.set_transform_static(stamped('turtle1', 'cam', 0.0), 'default_authority')
    assert buffer.all_frames_as_yaml() == (
        "turtle1: \n  parent: 'world'\n  broadcaster: 'default_authority'\n  rate: 3.000\n"
        '  most_recent_transform: 2.000000\n  oldest_transform: 1.000000\n'
        "  buffer_length: 1.000\ncam: \n  parent: 'turtle1'\n"
        "  broadcaster: 'default_authority'\n  rate: 10000.000\n"
        '  most_recent_transform: 0.000000\n  oldest_transform: 0.000000\n'
        '  buffer_length: 0.000\n')
    assert BufferCore().all_frames_as_yaml() == '[]'
    assert buffer.all_frames_as_string() == ('Frame turtle1 exists with parent world.\n'
                                             'Frame cam exists with parent turtle1.\n')


def test_velocity_from_two_lookups_an_averaging_interval_apart() -> None:
    buffer = BufferCore()
    for seconds in range(5):  # moving 3 m/s along x; turning 0.5 rad/s about z
        buffer.set_transform(stamped('parent', 'mover', seconds, (3.0 * seconds, 0.0, 0.0)),
                             'test')
        buffer.set_transform(stamped('parent', 'spinner', seconds, rpy=(0.0, 0.0, 0.5 * seconds)),
                             'test')
    interval = rclpy.duration.Duration(seconds=2)
    linear, angular = buffer.lookupVelocityCore('mover', 'parent', at(2.0), interval)
    assert linear == pytest.approx((3.0, 0.0, 0.0)) and angular == pytest.approx((0, 0, 0))
    # Time 0 is the latest data: the interval ends there (it cannot reach past 4 s).
    linear, angular = buffer.lookupVelocityCore('spinner', 'parent', LATEST, interval)
    assert linear == pytest.approx((0, 0, 0), abs=1e-9)
    assert angular == pytest.approx((0.0, 0.0, 0.5))
    full = buffer.lookupVelocityFullCore('spinner', 'parent', 'parent', (0, 0, 0), 'spinner',
                                         LATEST, interval)
    assert full == buffer.lookupVelocityCore('spinner', 'parent', LATEST, interval)
    with pytest.raises(LookupException):
        buffer.lookupVelocityCore('nowhere', 'parent', LATEST, interval)
