"""Broadcast a turtle's pose as the frame world -> <turtlename> (parameter `turtlename`)."""

from __future__ import annotations

import sys

import rclpy
from geometry_msgs.msg import TransformStamped
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.exceptions import InvalidTopicNameException
from rclpy.node import Node
from rclpy.validate_full_topic_name import validate_full_topic_name
from tf2_ros import TransformBroadcaster
from turtlesim.msg import Pose

from turtle_tf2_py.parameters import declare_frame
from turtle_tf2_py.quaternion import quaternion_from_euler


class FramePublisher(Node):
    def __init__(self) -> None:
        super().__init__('turtle_tf2_frame_publisher')
        self.turtlename = declare_frame(self, 'turtlename', 'turtle')
        topic = f'/{self.turtlename}/pose'
        try:
            validate_full_topic_name(topic)
        except InvalidTopicNameException:
            raise ValueError('turtlename must be a turtle name (letters, digits and '
                             f'underscores, not starting with a digit), got '
                             f'{self.turtlename!r}') from None
        self.tf_broadcaster = TransformBroadcaster(self)
        # Depth 1 as upstream: only the newest pose matters for the frame.
        self.subscription = self.create_subscription(Pose, topic, self.handle_turtle_pose, 1)

    def handle_turtle_pose(self, msg: Pose) -> None:
        t = TransformStamped()
        t.header.stamp = self.get_clock().now().to_msg()
        t.header.frame_id = 'world'
        t.child_frame_id = self.turtlename
        # The turtle lives in the plane: z = 0, and it turns about z only.
        t.transform.translation.x = msg.x
        t.transform.translation.y = msg.y
        t.transform.translation.z = 0.0
        q = quaternion_from_euler(0.0, 0.0, msg.theta)
        t.transform.rotation.x, t.transform.rotation.y = q[0], q[1]
        t.transform.rotation.z, t.transform.rotation.w = q[2], q[3]
        self.tf_broadcaster.sendTransform(t)


def main() -> int:
    with ros_session() as stop:
        try:
            node = FramePublisher()
        except ValueError as error:  # a bad turtlename: one line, nothing broadcast
            rclpy.logging.get_logger('turtle_tf2_frame_publisher').error(str(error))
            return 2
        spin_until_stopped(node, stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
