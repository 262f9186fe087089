"""`ros2 run demo_nodes_cpp one_off_timer`: a 2 s periodic timer that, every third call,
creates a new 1 s timer which cancels itself after its first call."""
import sys

from rclpy.node import Node

from demo_nodes_cpp.rclcpp_node import run_rclcpp_node


class OneOffTimerNode(Node):
    NAME = 'one_off_timer'

    def __init__(self) -> None:
        super().__init__(self.NAME)
        self.count = 0
        self.one_off_timer = None
        self.periodic_timer = self.create_timer(2.0, self.on_periodic)

    def on_periodic(self) -> None:
        log = self.get_logger()
        log.info('in periodic_timer callback')
        resetting = self.count % 3 == 0
        self.count += 1
        if resetting:
            log.info('  resetting one off timer')
            self.reset_one_off()
        else:
            log.info('  not resetting one off timer')

    def reset_one_off(self) -> None:
        if self.one_off_timer is not None:
            self.destroy_timer(self.one_off_timer)  # rclcpp frees the replaced timer
        self.one_off_timer = self.create_timer(1.0, self.on_one_off)

    def on_one_off(self) -> None:
        self.get_logger().info('in one_off_timer callback')
        self.one_off_timer.cancel()


def main() -> int:
    return run_rclcpp_node(OneOffTimerNode)


if __name__ == '__main__':
    sys.exit(main())
