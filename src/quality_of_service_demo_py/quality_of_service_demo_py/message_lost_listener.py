"""`ros2 run quality_of_service_demo_py message_lost_listener`: listens for Images on
message_lost_chatter (keep last 1) and reports messages the middleware lost on the way."""

from __future__ import annotations

import sys

from rclpy.event_handler import SubscriptionEventCallbacks
from rclpy.node import Node
from rclpy.time import Time
from sensor_msgs.msg import Image

from quality_of_service_demo_py.common_nodes import run


class MessageLostListener(Node):
    def __init__(self) -> None:
        super().__init__('message_lost_listener')
        self.subscription = self.create_subscription(
            Image, 'message_lost_chatter', self._message_callback, 1,
            event_callbacks=SubscriptionEventCallbacks(message_lost=self._message_lost))

    def _message_callback(self, message: Image) -> None:
        latency = self.get_clock().now() - Time.from_msg(message.header.stamp)
        self.get_logger().info(
            f'I heard an Image. Message single trip latency: [{latency.nanoseconds}]\n---')

    def _message_lost(self, status) -> None:
        self.get_logger().info(
            'Some messages were lost:\n>\tNumber of new lost messages: '
            f'{status.total_count_change} \n>\tTotal number of messages lost: '
            f'{status.total_count}')


def main() -> int:
    return run(lambda _executor: [MessageLostListener()])


if __name__ == '__main__':
    sys.exit(main())
