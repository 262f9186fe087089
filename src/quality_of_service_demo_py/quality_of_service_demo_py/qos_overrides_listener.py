"""`ros2 run quality_of_service_demo_py qos_overrides_listener`: hears qos_overrides_chatter
with QoS overridable by parameters, as qos_overrides_talker publishes it."""

from __future__ import annotations

import sys

from rclpy.node import Node
from rclpy.qos_overriding_options import QoSOverridingOptions
from std_msgs.msg import String

from quality_of_service_demo_py.common_nodes import run
from quality_of_service_demo_py.qos_overrides_talker import TOPIC, depth_at_most_10


class Listener(Node):
    def __init__(self) -> None:
        super().__init__('qos_overrides_listener')
        self.sub = self.create_subscription(
            String, TOPIC, self.chatter_callback, 10,
            qos_overriding_options=QoSOverridingOptions.with_default_policies(
                callback=depth_at_most_10))

    def chatter_callback(self, msg: String) -> None:
        self.get_logger().info(f'I heard: [{msg.data}]')


def main() -> int:
    return run(lambda _executor: [Listener()])


if __name__ == '__main__':
    sys.exit(main())
