"""Broadcast carrot1 circling turtle1 at 10 m, half a turn per second, at 10 Hz."""

from __future__ import annotations

import math
import sys

from geometry_msgs.msg import TransformStamped
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.node import Node
from tf2_ros import TransformBroadcaster


class DynamicFrameBroadcaster(Node):
    def __init__(self) -> None:
        super().__init__('dynamic_frame_tf2_broadcaster')
        self.tf_broadcaster = TransformBroadcaster(self)
        self.timer = self.create_timer(0.1, self.broadcast_timer_callback)

    def broadcast_timer_callback(self) -> None:
        now = self.get_clock().now()
        # The time with its fraction, as the C++ variant does: the offset changes
        # continuously (upstream's Python file takes whole seconds, where sin(k * pi) is 0).
        x = now.nanoseconds * 1e-9 * math.pi
        t = TransformStamped()
        t.header.stamp = now.to_msg()
        t.header.frame_id = 'turtle1'
        t.child_frame_id = 'carrot1'
        t.transform.translation.x = 10 * math.sin(x)
        t.transform.translation.y = 10 * math.cos(x)
        t.transform.translation.z = 0.0
        t.transform.rotation.w = 1.0
        self.tf_broadcaster.sendTransform(t)


def main() -> int:
    with ros_session() as stop:
        spin_until_stopped(DynamicFrameBroadcaster(), stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
