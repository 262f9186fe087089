"""`ros2 run demo_nodes_cpp set_and_get_parameters` (and `..._async`): sets six parameters of
its own and logs four of them back, with rclcpp's type names and value strings."""
import sys

from node_runtime.spinning import ros_session
from rclpy.node import Node
from rclpy.parameter import Parameter, parameter_value_to_python

from demo_nodes_cpp.parameters.self_client import answer, self_client
from demo_nodes_cpp.rclcpp_node import type_name, value_to_string

TYPES = Parameter.Type
VALUES = (('foo', TYPES.INTEGER, 2), ('bar', TYPES.STRING, 'hello'), ('baz', TYPES.DOUBLE, 1.45),
          ('foobar', TYPES.BOOL, True), ('foobarbaz', TYPES.BOOL_ARRAY, [True, False]),
          ('toto', TYPES.BYTE_ARRAY, [b'\xff', b'\x7f']))
EMPTY = {TYPES.INTEGER: 0, TYPES.STRING: '', TYPES.DOUBLE: 0.0, TYPES.BOOL: False}
SHOWN = ['foo', 'baz', 'foobarbaz', 'toto']


def main(name: str = 'set_and_get_parameters') -> int:
    with ros_session() as stop:
        node = Node(name)
        for parameter, kind, _value in VALUES:
            # An empty array has no type of its own in rclpy: declare it with its type.
            node.declare_parameter(parameter, EMPTY.get(kind, kind))
        client = self_client(node, stop)
        if client is None:
            return 0
        results = answer(node, client.set_parameters(
            [Parameter(parameter, kind, value) for parameter, kind, value in VALUES]), stop)
        for result in results.results if results else []:
            if not result.successful:
                node.get_logger().error(f'Failed to set parameter: {result.reason}')
        got = answer(node, client.get_parameters(SHOWN), stop)
        if got is not None:
            lines = ['']
            for parameter, value in zip(SHOWN, got.values, strict=True):
                shown = Parameter(parameter, TYPES(value.type), parameter_value_to_python(value))
                lines += [f'Parameter name: {parameter}',
                          f'Parameter value ({type_name(shown)}): {value_to_string(shown)}']
            node.get_logger().info('\n'.join(lines))
        node.destroy_node()
    return 0


def main_async() -> int:
    return main('set_and_get_parameters_async')


if __name__ == '__main__':
    sys.exit(main())
