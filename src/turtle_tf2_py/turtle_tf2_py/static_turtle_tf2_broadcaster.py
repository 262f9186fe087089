"""Broadcast one static frame under `world`, given on the command line.

    ros2 run turtle_tf2_py static_turtle_tf2_broadcaster mystaticturtle 0 0 1 0 0 0
"""

from __future__ import annotations

import math
import sys

import rclpy
from geometry_msgs.msg import TransformStamped
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.node import Node
from tf2_ros.static_transform_broadcaster import StaticTransformBroadcaster

from turtle_tf2_py.quaternion import quaternion_from_euler

FIELDS = ('x', 'y', 'z', 'roll', 'pitch', 'yaw')


class StaticFramePublisher(Node):
    """Broadcast transforms that never change: published once, latched for late listeners."""

    def __init__(self, child_frame: str, pose: tuple[float, ...]) -> None:
        super().__init__('static_turtle_tf2_broadcaster')
        self.tf_static_broadcaster = StaticTransformBroadcaster(self)
        self.make_transforms(child_frame, pose)

    def make_transforms(self, child_frame: str, pose: tuple[float, ...]) -> None:
        x, y, z, roll, pitch, yaw = pose
        t = TransformStamped()
        t.header.stamp = self.get_clock().now().to_msg()
        t.header.frame_id = 'world'
        t.child_frame_id = child_frame
        t.transform.translation.x = x
        t.transform.translation.y = y
        t.transform.translation.z = z
        q = quaternion_from_euler(roll, pitch, yaw)
        t.transform.rotation.x, t.transform.rotation.y = q[0], q[1]
        t.transform.rotation.z, t.transform.rotation.w = q[2], q[3]
        self.tf_static_broadcaster.sendTransform(t)


def parse_pose(values: list[str]) -> tuple[float, ...] | str:
    """The six numbers, or one line naming the first field that is not a finite number."""
    pose = []
    for field, text in zip(FIELDS, values, strict=True):
        try:
            value = float(text)
        except ValueError:
            value = math.nan
        if not math.isfinite(value):
            unit = 'metres' if field in 'xyz' else 'radians'
            return f'{field} must be a finite number ({unit}), got {text!r}'
        pose.append(value)
    return tuple(pose)


def main() -> int:
    logger = rclpy.logging.get_logger('logger')
    argv = rclpy.utilities.remove_ros_args(sys.argv)
    if len(argv) != 8:
        logger.info('Invalid number of parameters. Usage: \n'
                    '$ ros2 run turtle_tf2_py static_turtle_tf2_broadcaster '
                    'child_frame_name x y z roll pitch yaw')
        return 1
    child_frame = argv[1]
    if child_frame == 'world':
        logger.info('Your static turtle name cannot be "world"')
        return 2
    if not child_frame or child_frame.startswith('/'):
        # tf2 refuses such ids at every listener; say it here, once.
        logger.error(f'child_frame_name must be a non-empty frame id not starting with "/", '
                     f'got {child_frame!r}')
        return 2
    pose = parse_pose(argv[2:])
    if isinstance(pose, str):
        logger.error(pose)
        return 2
    with ros_session() as stop:
        spin_until_stopped(StaticFramePublisher(child_frame, pose), stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
