"""`ros2 run demo_nodes_cpp parameter_blackboard`: a node that accepts any parameter, set at
start-up (`-p name:=value`, a parameter file) or later (`ros2 param set`). Upstream's is an
rclcpp node: it also holds rclcpp's qos_overrides parameters and /parameter_events
subscription, and counts them among those it serves."""
import sys

from node_runtime.rclcpp_parity import RclcppParameters, declare_rclcpp_parameters
from node_runtime.spinning import ros_session, spin_until_stopped
from rcl_interfaces.srv import ListParameters
from rclpy.node import Node


class ParameterBlackboard(RclcppParameters, Node):
    def __init__(self) -> None:
        super().__init__('parameter_blackboard', allow_undeclared_parameters=True,
                         automatically_declare_parameters_from_overrides=True)
        declare_rclcpp_parameters(self)
        served = self.list_parameters([], ListParameters.Request.DEPTH_RECURSIVE).names
        self.get_logger().info(
            f"Parameter blackboard node named '{self.get_fully_qualified_name()}' ready, and "
            f"serving '{len(served)}' parameters already!")

    def list_parameters(self, prefixes, depth):
        # rclcpp keeps parameters in a map, so its listing is in name order (async_param_client
        # prints it); rclpy lists them in the order they were set.
        result = super().list_parameters(prefixes, depth)
        result.names, result.prefixes = sorted(result.names), sorted(result.prefixes)
        return result


def main() -> int:
    with ros_session() as stop:
        spin_until_stopped(ParameterBlackboard(), stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
