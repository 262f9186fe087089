"""`ros2 run demo_nodes_cpp even_parameters_node`: takes any parameter (undeclared ones too)
as long as it is an even integer; deleting is allowed."""
import sys

from node_runtime.rclcpp_parity import declare_rclcpp_parameters
from rcl_interfaces.msg import SetParametersResult
from rclpy.node import Node
from rclpy.parameter import Parameter

from demo_nodes_cpp.rclcpp_node import run_rclcpp_node, value_to_string


class EvenParameterNode(Node):
    def __init__(self) -> None:
        super().__init__('even_parameters_node', allow_undeclared_parameters=True)
        log = self.get_logger()
        log.info('This example node shows a parameter callback that rejects')
        log.info('all parameter updates except for those that set an even integer.')
        log.info("Try running 'ros2 param set /even_parameters_node myint 2' to")
        log.info('successfully set a parameter.')
        # rclcpp declares its own parameters before the node's callback can refuse them.
        declare_rclcpp_parameters(self)
        self.add_on_set_parameters_callback(self.on_set)

    def on_set(self, parameters: list[Parameter]) -> SetParametersResult:
        log = self.get_logger()
        result = SetParametersResult(successful=True)
        for parameter in parameters:
            if parameter.type_ == Parameter.Type.NOT_SET:
                log.info(f"parameter '{parameter.name}' deleted successfully")
            elif parameter.type_ == Parameter.Type.INTEGER:
                if parameter.value % 2 != 0:
                    log.info(f"Requested value '{parameter.value}' for parameter "
                             f"'{parameter.name}' is not an even number: rejecting change...")
                    result.successful, result.reason = False, 'only even integers can be set'
                else:
                    log.info(f"parameter '{parameter.name}' has changed and is now: "
                             f'{value_to_string(parameter)}')
            else:
                log.info('only integer parameters can be set\nrequested value for parameter '
                         f"'{parameter.name}' is not an even number, rejecting change...")
                result.successful = False
                result.reason = 'only integer parameters can be set'
        return result


def main() -> int:
    return run_rclcpp_node(EvenParameterNode)


if __name__ == '__main__':
    sys.exit(main())
