"""`ros2 run demo_nodes_cpp listener`: the same node as demo_nodes_py's listener."""
import sys

from demo_nodes_py.topics.listener import Listener

from demo_nodes_cpp.rclcpp_node import run_rclcpp_node


def main() -> int:
    return run_rclcpp_node(Listener)


if __name__ == '__main__':
    sys.exit(main())
