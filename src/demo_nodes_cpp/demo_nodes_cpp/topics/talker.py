"""`ros2 run demo_nodes_cpp talker`: upstream's C++ talker counts from 1, quotes with '...'
and keeps the last 7 messages; otherwise it is demo_nodes_py's."""
import sys

from demo_nodes_py.topics import talker

from demo_nodes_cpp.rclcpp_node import run_rclcpp_node


class Talker(talker.Talker):
    FIRST_COUNT = 1
    QOS_DEPTH = 7
    LOG_LINE = "Publishing: '{}'"


def main() -> int:
    return run_rclcpp_node(Talker)


if __name__ == '__main__':
    sys.exit(main())
