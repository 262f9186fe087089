"""`ros2 run lifecycle lifecycle_listener`: lc_listener logs lc_talker's data and every
transition event it publishes."""

from __future__ import annotations

import sys

from lifecycle_msgs.msg import TransitionEvent
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.node import Node
from std_msgs.msg import String


class LifecycleListener(Node):
    def __init__(self) -> None:
        super().__init__('lc_listener')
        self.create_subscription(String, 'lifecycle_chatter', self.data_callback, 10)
        self.create_subscription(TransitionEvent, '/lc_talker/transition_event',
                                 self.notification_callback, 10)

    def data_callback(self, msg: String) -> None:
        self.get_logger().info(f'data_callback: {msg.data}')

    def notification_callback(self, msg: TransitionEvent) -> None:
        self.get_logger().info(f'notify callback: Transition from state '
                               f'{msg.start_state.label} to {msg.goal_state.label}')


def main() -> int:
    with ros_session() as stop:
        spin_until_stopped(LifecycleListener(), stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
