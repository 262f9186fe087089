"""What every demo_nodes_cpp stand-in shares: rclcpp's graph presence (qos_overrides
parameters, a /parameter_events subscription; node_runtime.rclcpp_parity) and rclcpp's
spelling of parameter types and values (`Parameter::get_type_name`, `value_to_string`)."""
from __future__ import annotations

from collections.abc import Callable

from node_runtime.rclcpp_parity import PREFIX, declare_rclcpp_parameters
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.node import Node
from rclpy.parameter import Parameter


def type_name(parameter: Parameter) -> str:
    return 'not set' if parameter.type_ == Parameter.Type.NOT_SET else \
        parameter.type_.name.lower()


def value_to_string(parameter: Parameter) -> str:
    value, kind = parameter.value, parameter.type_
    if kind == Parameter.Type.NOT_SET:
        return 'not set'
    if kind == Parameter.Type.BOOL:
        return 'true' if value else 'false'
    if kind == Parameter.Type.DOUBLE:
        return f'{value:f}'  # std::to_string
    if kind == Parameter.Type.BYTE_ARRAY:
        return '[' + ', '.join(hex(item[0] if isinstance(item, bytes) else item)
                               for item in value) + ']'
    if kind == Parameter.Type.BOOL_ARRAY:
        return '[' + ', '.join('true' if item else 'false' for item in value) + ']'
    if kind in (Parameter.Type.INTEGER_ARRAY, Parameter.Type.DOUBLE_ARRAY,
                Parameter.Type.STRING_ARRAY):
        return '[' + ', '.join(f'{item:g}' if isinstance(item, float) else str(item)
                               for item in value) + ']'
    return str(value)


def run_rclcpp_node(factory: Callable[[], Node]) -> int:
    """main() of a long-running stand-in: the node, with rclcpp's extras, until Ctrl-C."""
    with ros_session() as stop:
        node = factory()
        if not node.has_parameter(PREFIX + 'depth'):  # a node may declare them itself first
            declare_rclcpp_parameters(node)
        spin_until_stopped(node, stop)
    return 0


