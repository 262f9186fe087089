"""`ros2 run ros2lifecycle_test_fixtures simple_lifecycle_node`: a managed node
(test_lifecycle_node) whose every transition succeeds and logs one line, the fixture that
`ros2 lifecycle` is tested against. Upstream's is an rclcpp_lifecycle node; this one is on
rclpy.lifecycle, with its log lines.
"""

from __future__ import annotations

import sys

from node_runtime.rclcpp_parity import RclcppLifecycleTransitions
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.lifecycle import Node, State, TransitionCallbackReturn


class SimpleLifecycleNode(RclcppLifecycleTransitions, Node):
    def __init__(self, node_name: str = 'test_lifecycle_node') -> None:
        super().__init__(node_name)

    def on_configure(self, state: State) -> TransitionCallbackReturn:
        return self._succeed('on_configure() is called.')

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        return self._succeed('on_activate() is called.')

    def on_deactivate(self, state: State) -> TransitionCallbackReturn:
        return self._succeed('on_deactivate() is called.')

    def on_cleanup(self, state: State) -> TransitionCallbackReturn:
        return self._succeed('on cleanup is called.')

    def on_shutdown(self, state: State) -> TransitionCallbackReturn:
        return self._succeed(f'on shutdown is called from state {state.label}.')

    def _succeed(self, line: str) -> TransitionCallbackReturn:
        self.get_logger().info(line)
        return TransitionCallbackReturn.SUCCESS


def main() -> int:
    with ros_session() as stop:
        spin_until_stopped(SimpleLifecycleNode(), stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
