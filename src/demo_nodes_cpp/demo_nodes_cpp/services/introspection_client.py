"""`ros2 run demo_nodes_cpp introspection_client`: demo_nodes_py's introspection client node
(parameter `client_configure_introspection`) on its own."""
import sys

from demo_nodes_py.services.introspection import IntrospectionClientNode

from demo_nodes_cpp.rclcpp_node import run_rclcpp_node


def main() -> int:
    return run_rclcpp_node(IntrospectionClientNode)


if __name__ == '__main__':
    sys.exit(main())
