"""`ros2 run demo_nodes_cpp list_parameters` (and `list_parameters_async`): sets six
parameters of its own and lists those under the prefixes `foo` and `bar`."""
import sys

from node_runtime.spinning import ros_session
from rclpy.node import Node
from rclpy.parameter import Parameter

from demo_nodes_cpp.parameters.self_client import answer, self_client

VALUES = (('foo', 2), ('bar', 'hello'), ('baz', 1.45), ('foo.first', 8), ('foo.second', 42),
          ('foobar', True))


def main(name: str = 'list_parameters') -> int:
    with ros_session() as stop:
        node = Node(name)
        # rclcpp lists parameters in name order, rclpy in declaration order.
        for parameter, value in sorted(VALUES):
            node.declare_parameter(parameter, type(value)())
        client = self_client(node, stop)
        if client is None:
            return 0
        node.get_logger().info('Setting parameters...')
        answer(node, client.set_parameters(
            [Parameter(parameter, value=value) for parameter, value in VALUES]), stop)
        node.get_logger().info('Listing parameters...')
        listed = answer(node, client.list_parameters(['foo', 'bar'], 10), stop)
        if listed is not None:
            lines = ['', 'Parameter names:', *(f' {name}' for name in listed.result.names),
                     'Parameter prefixes:', *(f' {prefix}' for prefix in listed.result.prefixes)]
            node.get_logger().info('\n'.join(lines))
        node.destroy_node()
    return 0


def main_async() -> int:
    return main('list_parameters_async')


if __name__ == '__main__':
    sys.exit(main())
