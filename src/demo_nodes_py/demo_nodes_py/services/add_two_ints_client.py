"""`ros2 run demo_nodes_py add_two_ints_client`: asks /add_two_ints for 2 + 3, logs the sum
and exits."""
import sys

import rclpy
from example_interfaces.srv import AddTwoInts
from node_runtime.spinning import ros_session

from demo_nodes_py.services.client_wait import spin_until_done, wait_for_service


def main() -> int:
    with ros_session() as stop:
        node = rclpy.create_node('add_two_ints_client')
        cli = node.create_client(AddTwoInts, 'add_two_ints')
        if wait_for_service(cli, stop):
            future = cli.call_async(AddTwoInts.Request(a=2, b=3))
            if spin_until_done(node, future, stop):
                if future.result() is not None:
                    node.get_logger().info(f'Result of add_two_ints: {future.result().sum}')
                else:
                    node.get_logger().error(
                        f'Exception while calling service: {future.exception()!r}')
        node.destroy_node()
    return 0


if __name__ == '__main__':
    sys.exit(main())
