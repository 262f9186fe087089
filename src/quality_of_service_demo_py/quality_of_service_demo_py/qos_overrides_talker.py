"""`ros2 run quality_of_service_demo_py qos_overrides_talker`: 'Hello World: N' once a second
on qos_overrides_chatter, whose QoS parameters (qos_overrides./qos_overrides_chatter.
publisher.depth, ...) may be set at start-up; a depth above 10 is refused."""

from __future__ import annotations

import sys

from rclpy.node import Node
from rclpy.qos_overriding_options import QosCallbackResult, QoSOverridingOptions
from std_msgs.msg import String

from quality_of_service_demo_py.common_nodes import run

TOPIC = 'qos_overrides_chatter'


def depth_at_most_10(qos) -> QosCallbackResult:
    """The overrides' check both nodes register: a depth above 10 is refused."""
    result = QosCallbackResult()
    result.successful = qos.depth <= 10
    if not result.successful:
        result.reason = 'expected qos depth less than 10'
    return result


class Talker(Node):
    def __init__(self) -> None:
        super().__init__('qos_overrides_talker')
        self.i = 0
        self.pub = self.create_publisher(
            String, TOPIC, 10, qos_overriding_options=QoSOverridingOptions.with_default_policies(
                callback=depth_at_most_10))
        self.create_timer(1.0, self.timer_callback)

    def timer_callback(self) -> None:
        msg = String(data=f'Hello World: {self.i}')
        self.i += 1
        self.get_logger().info(f'Publishing: "{msg.data}"')
        self.pub.publish(msg)


def main() -> int:
    return run(lambda _executor: [Talker()])


if __name__ == '__main__':
    sys.exit(main())
