""""Using URDF with robot_state_publisher (Python)": the r2d2 demo's frames reach a tf2
listener, with robot_state_publisher's fixed joints latched on /tf_static and the moving
ones on /tf, as the page's RViz view shows them."""
from __future__ import annotations

import math

import pytest
import rclpy.time
from tf2_ros import Buffer, TransformListener

LATEST = rclpy.time.Time()


def test_r2d2_demo_frames_through_tf2(launch, probe) -> None:
    demo = launch(argv=['ros2', 'launch', 'urdf_tutorial_r2d2', 'demo.launch.py'])
    buffer = Buffer()
    listener = TransformListener(buffer, probe.node)
    try:
        probe.spin_until(lambda: buffer.can_transform('odom', 'box', LATEST), 30,
                         'odom -> box through every r2d2 joint')
        # state_publisher drives axis around a 2 m circle in odom.
        axis = buffer.lookup_transform('odom', 'axis', LATEST).transform.translation
        assert math.hypot(axis.x, axis.y) == pytest.approx(2.0, abs=0.01)
        # /tf moves: half a second later r2d2 stands elsewhere on that circle.
        probe.spin_for(0.5)
        later = buffer.lookup_transform('odom', 'axis', LATEST).transform.translation
        assert math.hypot(later.x, later.y) == pytest.approx(2.0, abs=0.01)
        assert math.dist((axis.x, axis.y), (later.x, later.y)) > 0.05, (axis, later)
        # leg1connect is fixed: latched on /tf_static, answered at any time.
        assert buffer.can_transform('axis', 'leg1', rclpy.time.Time(seconds=1)) is True
        frames = buffer.all_frames_as_yaml()
        for child, parent in (('body', 'axis'), ('head', 'body'), ('rod', 'head'),
                              ('box', 'rod'), ('leg1', 'axis'), ('leg2', 'axis')):
            assert f"{child}: \n  parent: '{parent}'" in frames, frames
    finally:
        listener.unregister()
    assert 'Traceback' not in demo.output

