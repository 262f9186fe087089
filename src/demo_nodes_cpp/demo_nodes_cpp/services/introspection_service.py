"""`ros2 run demo_nodes_cpp introspection_service`: demo_nodes_py's introspection service node
(parameter `service_configure_introspection`) on its own."""
import sys

from demo_nodes_py.services.introspection import IntrospectionServiceNode

from demo_nodes_cpp.rclcpp_node import run_rclcpp_node


def main() -> int:
    return run_rclcpp_node(IntrospectionServiceNode)


if __name__ == '__main__':
    sys.exit(main())
