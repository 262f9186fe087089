"""`ros2 run demo_nodes_cpp reuse_timer`: one_off_timer's behaviour with one timer, created
cancelled and reset (not re-created) every third periodic call."""
import sys

from demo_nodes_cpp.rclcpp_node import run_rclcpp_node
from demo_nodes_cpp.timers.one_off_timer import OneOffTimerNode


class ReuseTimerNode(OneOffTimerNode):
    NAME = 'reuse_timer'

    def __init__(self) -> None:
        super().__init__()
        self.one_off_timer = self.create_timer(1.0, self.on_one_off)
        self.one_off_timer.cancel()  # so that it does not run the first time

    def reset_one_off(self) -> None:
        self.one_off_timer.reset()


def main() -> int:
    return run_rclcpp_node(ReuseTimerNode)


if __name__ == '__main__':
    sys.exit(main())
