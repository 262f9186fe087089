"""`ros2 run demo_nodes_cpp set_parameters_callback`: rclcpp's variant of the three parameter
callbacks (node `set_param_callback_node`): `param1` may not exceed 5.0, `param2` may not go
below -5.0, setting `param1` sets `param2` to 4.0, and each accepted value is logged."""
import sys

from rcl_interfaces.msg import SetParametersResult
from rclpy.node import Node
from rclpy.parameter import Parameter

from demo_nodes_cpp.rclcpp_node import run_rclcpp_node

INTRODUCTION = (
    'This node demonstrates the use of parameter callbacks.',
    'As an example, it exhibits the following behavior:',
    " * Two parameters of type double are declared in the node: 'param1' and 'param2'",
    " * 'param1' cannot be set to a value > 5.0",
    " * 'param2' cannot be set to a value < -5.0",
    " * Each time 'param1' is set, 'param2' is automatically set to 4.0",
    " * Member variables 'value_1_' and 'value_2_' are updated upon change of the parameters.",
    'To try it out set a parameter, e.g.:',
    '  ros2 param set set_param_callback_node param1 10.0',
    '  ros2 param set set_param_callback_node param1 3.0',
    'The first command will fail.',
    "The 2nd command will set 'param1' to 3.0 and 'param2' to 4.0.",
)
LIMITS = {'param1': (lambda value: value > 5.0, "cannot set 'param1' > 5.0"),
          'param2': (lambda value: value < -5.0, "cannot set 'param2' < -5.0")}


class SetParametersCallback(Node):
    def __init__(self) -> None:
        super().__init__('set_param_callback_node')
        self.value_1 = self.declare_parameter('param1', 1.0).value
        self.value_2 = self.declare_parameter('param2', 2.0).value
        self.add_pre_set_parameters_callback(self.pre_set)
        self.add_on_set_parameters_callback(self.on_set)
        self.add_post_set_parameters_callback(self.post_set)
        for line in INTRODUCTION:
            self.get_logger().info(line)

    def pre_set(self, parameters: list[Parameter]) -> list[Parameter]:
        if any(parameter.name == 'param1' for parameter in parameters):
            return [*parameters, Parameter('param2', Parameter.Type.DOUBLE, 4.0)]
        return parameters

    def on_set(self, parameters: list[Parameter]) -> SetParametersResult:
        for parameter in parameters:
            too_far, reason = LIMITS.get(parameter.name, (lambda _value: False, ''))
            if too_far(parameter.value):
                return SetParametersResult(successful=False, reason=reason)
        return SetParametersResult(successful=True)

    def post_set(self, parameters: list[Parameter]) -> None:
        for parameter in parameters:
            if parameter.name == 'param1':
                self.value_1 = parameter.value
                self.get_logger().info(f"Member variable 'value_1_' set to: {self.value_1:f}.")
            if parameter.name == 'param2':
                self.value_2 = parameter.value
                self.get_logger().info(f"Member variable 'value_2_' set to: {self.value_2:f}.")


def main() -> int:
    return run_rclcpp_node(SetParametersCallback)


if __name__ == '__main__':
    sys.exit(main())
