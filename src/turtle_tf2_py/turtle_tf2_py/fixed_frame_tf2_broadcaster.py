"""Broadcast carrot1, fixed 2 m to the left of turtle1 (y axis of turtle1), at 10 Hz."""

from __future__ import annotations

import sys

from geometry_msgs.msg import TransformStamped
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.node import Node
from tf2_ros import TransformBroadcaster


class FixedFrameBroadcaster(Node):
    def __init__(self) -> None:
        super().__init__('fixed_frame_tf2_broadcaster')
        self.tf_broadcaster = TransformBroadcaster(self)
        self.timer = self.create_timer(0.1, self.broadcast_timer_callback)

    def broadcast_timer_callback(self) -> None:
        t = TransformStamped()
        t.header.stamp = self.get_clock().now().to_msg()
        t.header.frame_id = 'turtle1'
        t.child_frame_id = 'carrot1'
        t.transform.translation.x = 0.0
        t.transform.translation.y = 2.0
        t.transform.translation.z = 0.0
        t.transform.rotation.w = 1.0  # x, y, z stay 0: no rotation
        self.tf_broadcaster.sendTransform(t)


def main() -> int:
    with ros_session() as stop:
        spin_until_stopped(FixedFrameBroadcaster(), stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
