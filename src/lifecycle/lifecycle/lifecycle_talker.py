"""`ros2 run lifecycle lifecycle_talker`: a managed node (lc_talker) that publishes
'Lifecycle HelloWorld #n' on lifecycle_chatter once a second, delivered only while active.

The publisher and its timer exist from configure to cleanup/shutdown; publish() is called in
every state and the lifecycle publisher drops what is published while inactive. Upstream's
is an rclcpp node; this one, on rclpy.lifecycle, prints its lines. lifecycle_py's talker is
this class with the rclpy demo's texts.
"""

from __future__ import annotations

import sys
import time

from node_runtime.rclcpp_parity import RclcppLifecycleTransitions
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.lifecycle import Node, Publisher, State, TransitionCallbackReturn
from rclpy.timer import Timer
from std_msgs.msg import String


class LifecycleTalker(RclcppLifecycleTransitions, Node):
    FIRST_COUNT = 1
    INACTIVE_TEXT = 'Lifecycle publisher is currently inactive. Messages are not published.'
    CLEANUP_TEXT = 'on cleanup is called.'
    SHUTDOWN_TEXT = 'on shutdown is called from state {state}.'
    ACTIVATE_SECONDS = 2.0  # upstream sleeps in on_activate to show a transition takes time

    def __init__(self, node_name: str = 'lc_talker') -> None:
        self._count = self.FIRST_COUNT
        self._pub: Publisher | None = None
        self._timer: Timer | None = None
        super().__init__(node_name)

    def publish(self) -> None:
        msg = String(data=f'Lifecycle HelloWorld #{self._count}')
        self._count += 1
        if self._pub is None or not self._pub.is_activated:
            self.get_logger().info(self.INACTIVE_TEXT)
        else:
            self.get_logger().info(f'Lifecycle publisher is active. Publishing: [{msg.data}]')
        if self._pub is not None:
            self._pub.publish(msg)

    def on_configure(self, state: State) -> TransitionCallbackReturn:
        self._pub = self.create_lifecycle_publisher(String, 'lifecycle_chatter', 10)
        self._timer = self.create_timer(1.0, self.publish)
        self.get_logger().info('on_configure() is called.')
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        result = super().on_activate(state)  # enables the lifecycle publisher
        self.get_logger().info('on_activate() is called.')
        time.sleep(self.ACTIVATE_SECONDS)
        return result

    def on_deactivate(self, state: State) -> TransitionCallbackReturn:
        result = super().on_deactivate(state)
        self.get_logger().info('on_deactivate() is called.')
        return result

    def on_cleanup(self, state: State) -> TransitionCallbackReturn:
        self._release()
        self.get_logger().info(self.CLEANUP_TEXT)
        return TransitionCallbackReturn.SUCCESS

    def on_shutdown(self, state: State) -> TransitionCallbackReturn:
        self._release()
        self.get_logger().info(self.SHUTDOWN_TEXT.format(state=state.label))
        return TransitionCallbackReturn.SUCCESS

    def _release(self) -> None:
        if self._timer is not None:
            self.destroy_timer(self._timer)
        if self._pub is not None:
            self.destroy_lifecycle_publisher(self._pub)
        self._timer = self._pub = None


def run(talker_class: type[LifecycleTalker]) -> int:
    with ros_session() as stop:
        spin_until_stopped(talker_class(), stop)
    return 0


def main() -> int:
    return run(LifecycleTalker)


if __name__ == '__main__':
    sys.exit(main())
