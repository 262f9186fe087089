"""tf2_ros.Buffer's Python API as upstream's: lookups that wait up to `timeout=` for data that
arrives on another thread, can_transform with its debug tuple, the futures of
wait_for_transform_async, and Buffer.transform() of the stamped types tf2_geometry_msgs
registers (points, vectors, poses, covariances). In-process: Buffer is filled here as a
TransformListener's thread fills it; the listener over DDS is in test_tf2_tools.py.
"""
from __future__ import annotations

import math
import threading
import time

import pytest
import rclpy.duration
import rclpy.time
import tf2_geometry_msgs  # registers the stamped types, as upstream
from geometry_msgs.msg import (
    AccelStamped,
    PointStamped,
    PoseStamped,
    PoseWithCovarianceStamped,
    TransformStamped,
    Vector3Stamped,
)
from tf2_py import LookupException
from tf2_py.maths import euler_from_quaternion, quaternion_from_euler
from tf2_ros import Buffer, TypeException

LATEST = rclpy.time.Time()


def seconds(value: float) -> rclpy.duration.Duration:
    return rclpy.duration.Duration(nanoseconds=round(value * 1e9))


def robot_in_world(stamp_s: float = 10.0) -> TransformStamped:
    """robot 1 m along world's x, turned 90 degrees left."""
    t = TransformStamped()
    t.header.frame_id, t.child_frame_id = 'world', 'robot'
    t.header.stamp = rclpy.time.Time(seconds=stamp_s).to_msg()
    t.transform.translation.x = 1.0
    x, y, z, w = quaternion_from_euler(0.0, 0.0, math.pi / 2)
    t.transform.rotation.x, t.transform.rotation.y = x, y
    t.transform.rotation.z, t.transform.rotation.w = z, w
    return t


@pytest.fixture
def buffer() -> Buffer:
    filled = Buffer()
    filled.set_transform(robot_in_world(), 'test')
    return filled


def in_robot(message):
    message.header.frame_id = 'robot'
    message.header.stamp = rclpy.time.Time(seconds=10.0).to_msg()
    return message


def test_transform_point_vector_and_pose(buffer: Buffer) -> None:
    point = in_robot(PointStamped())
    point.point.x = 1.0
    moved = buffer.transform(point, 'world')
    assert moved.header.frame_id == 'world'
    assert (moved.point.x, moved.point.y, moved.point.z) == pytest.approx((1.0, 1.0, 0.0))

    vector = in_robot(Vector3Stamped())
    vector.vector.x = 1.0
    turned = buffer.transform(vector, 'world')  # rotated, never translated
    assert (turned.vector.x, turned.vector.y, turned.vector.z) == pytest.approx((0.0, 1.0, 0.0))

    pose = in_robot(PoseStamped())
    pose.pose.position.y = 2.0
    pose.pose.orientation.w = 1.0
    placed = buffer.transform(pose, 'world')
    assert (placed.pose.position.x, placed.pose.position.y) == pytest.approx((-1.0, 0.0))
    q = placed.pose.orientation
    assert euler_from_quaternion((q.x, q.y, q.z, q.w))[2] == pytest.approx(math.pi / 2)


def test_transform_rotates_the_covariance(buffer: Buffer) -> None:
    pose = in_robot(PoseWithCovarianceStamped())
    pose.pose.pose.orientation.w = 1.0
    covariance = [0.0] * 36
    covariance[0], covariance[7] = 1.0, 4.0  # var(x), var(y) in robot
    pose.pose.covariance = covariance
    result = buffer.transform(pose, 'world').pose.covariance
    # Turned 90 degrees: robot's x is world's y.
    assert (result[0], result[7]) == pytest.approx((4.0, 1.0))


def test_transform_of_an_unregistered_type_is_refused(buffer: Buffer) -> None:
    unknown = in_robot(AccelStamped())  # stamped, but tf2_geometry_msgs registers no transform
    with pytest.raises(TypeException, match='is not loaded or supported'):
        buffer.transform(unknown, 'world')


def test_lookup_waits_up_to_timeout_for_data_from_another_thread() -> None:
    buffer = Buffer()
    arrival = threading.Timer(0.2, lambda: buffer.set_transform(robot_in_world(), 'late'))
    arrival.start()
    try:
        started = time.monotonic()
        found = buffer.lookup_transform('world', 'robot', LATEST, timeout=seconds(5.0))
        waited = time.monotonic() - started
    finally:
        arrival.cancel()
    assert found.child_frame_id == 'robot'
    assert 0.15 <= waited < 5.0, waited  # woken by the data, not by the timeout


def test_lookup_gives_up_after_timeout_with_upstreams_exception() -> None:
    buffer = Buffer()
    started = time.monotonic()
    with pytest.raises(LookupException, match='"world" passed to lookupTransform argument '
                                              'target_frame does not exist'):
        buffer.lookup_transform('world', 'robot', LATEST, timeout=seconds(0.3))
    assert time.monotonic() - started >= 0.3


def test_can_transform_and_its_debug_tuple(buffer: Buffer) -> None:
    assert buffer.can_transform('world', 'robot', LATEST)
    able, why = buffer.can_transform('world', 'nowhere', LATEST, return_debug_tuple=True)
    assert not able
    assert 'nowhere' in why


def test_wait_for_transform_async_completes_when_data_arrives() -> None:
    buffer = Buffer()
    future = buffer.wait_for_transform_async('world', 'robot', LATEST)
    assert not future.done()
    buffer.set_transform(robot_in_world(), 'test')
    assert future.done()
    assert future.result().transform.translation.x == pytest.approx(1.0)


def test_lookup_transform_full_through_a_fixed_frame() -> None:
    """Where robot was at t=10 s, seen from where it is at t=11 s (it moved 1 m on in world)."""
    buffer = Buffer()
    buffer.set_transform(robot_in_world(10.0), 'test')
    later = robot_in_world(11.0)
    later.transform.translation.x = 2.0
    buffer.set_transform(later, 'test')
    result = buffer.lookup_transform_full('robot', rclpy.time.Time(seconds=11.0), 'robot',
                                          rclpy.time.Time(seconds=10.0), 'world')
    # 1 m behind along world's x, which is robot's -y after the 90 degree turn.
    v = result.transform.translation
    assert (v.x, v.y, v.z) == pytest.approx((0.0, 1.0, 0.0), abs=1e-9)


def test_transformed_orientations_have_w_at_least_zero() -> None:
    # Half a turn about x applied to half a turn about x: the identity. The quaternion
    # product is w = -1; upstream gives the same rotation as w = +1, and so do we.
    half_turn = TransformStamped()
    half_turn.header.frame_id, half_turn.child_frame_id = 'a', 'b'
    half_turn.transform.rotation.x, half_turn.transform.rotation.w = 1.0, 0.0
    for pose_type in (PoseStamped, PoseWithCovarianceStamped):
        pose = pose_type()
        inner = pose.pose.pose if pose_type is PoseWithCovarianceStamped else pose.pose
        inner.orientation.x, inner.orientation.w = 1.0, 0.0
        result = tf2_geometry_msgs.do_transform_pose_stamped(pose, half_turn) \
            if pose_type is PoseStamped else \
            tf2_geometry_msgs.do_transform_pose_with_covariance_stamped(pose, half_turn)
        out = result.pose.pose if pose_type is PoseWithCovarianceStamped else result.pose
        q = out.orientation
        assert (q.x, q.y, q.z, q.w) == (0.0, 0.0, 0.0, 1.0), pose_type


def test_buffer_takes_rclpy_time_stamps_and_set_transform_returns_none() -> None:
    buffer = Buffer()
    t = robot_in_world()
    t.header.stamp = rclpy.time.Time(seconds=2.5)  # an rclpy Time, as upstream's tests set it
    assert buffer.set_transform(t, 'test') is None
    found = buffer.lookup_transform('world', 'robot', rclpy.time.Time(seconds=2.5))
    assert (found.header.stamp.sec, found.header.stamp.nanosec) == (2, 500_000_000)


def test_tf2_ros_namespace_holds_what_upstreams_star_imports_bring() -> None:
    # The URDF tutorial's state_publisher.py imports both from tf2_ros.
    from tf2_ros import (  # noqa: F401
        BufferClient,
        Duration,
        Time,
        TransformBroadcaster,
        TransformStamped,
    )
    assert TransformStamped is robot_in_world().__class__
