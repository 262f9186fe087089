"""`ros2 run demo_nodes_py set_parameters_callback`: the three parameter callbacks. Setting
`param1` also sets `param2` to 4.0 (pre-set), both are accepted (on-set), and the node keeps
its own copies up to date (post-set)."""
from __future__ import annotations

import sys

from node_runtime.spinning import ros_session, spin_until_stopped
from rcl_interfaces.msg import SetParametersResult
from rclpy.node import Node
from rclpy.parameter import Parameter


class SetParametersCallback(Node):
    def __init__(self) -> None:
        super().__init__('set_parameters_callback')
        self.internal_tracked_param_1 = self.declare_parameter('param1', 0.0).value
        self.internal_tracked_param_2 = self.declare_parameter('param2', 0.0).value
        self.add_pre_set_parameters_callback(self.pre_set)
        self.add_on_set_parameters_callback(self.on_set)
        self.add_post_set_parameters_callback(self.post_set)

    def pre_set(self, parameters: list[Parameter]) -> list[Parameter]:
        if any(parameter.name == 'param1' for parameter in parameters):
            return [*parameters, Parameter('param2', Parameter.Type.DOUBLE, 4.0)]
        return parameters

    def on_set(self, parameters: list[Parameter]) -> SetParametersResult:
        result = SetParametersResult()
        for parameter in parameters:
            if parameter.name in ('param1', 'param2'):
                result.successful = True
                result.reason = f'success {parameter.name}'
        return result

    def post_set(self, parameters: list[Parameter]) -> None:
        for parameter in parameters:
            if parameter.name == 'param1':
                self.internal_tracked_param_1 = parameter.value
            elif parameter.name == 'param2':
                self.internal_tracked_param_2 = parameter.value


def main() -> int:
    with ros_session() as stop:
        spin_until_stopped(SetParametersCallback(), stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
