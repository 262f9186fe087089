"""`ros2 run demo_nodes_cpp add_two_ints_client`: asks /add_two_ints for 2 + 3 and exits;
waiting is logged (rclcpp's client logs it, the Python one prints it)."""
import sys

import rclpy
from demo_nodes_py.services.client_wait import spin_until_done, wait_for_service
from example_interfaces.srv import AddTwoInts
from node_runtime.spinning import ros_session


def main() -> int:
    with ros_session() as stop:
        node = rclpy.create_node('add_two_ints_client')
        client = node.create_client(AddTwoInts, 'add_two_ints')
        if not wait_for_service(client, stop, node.get_logger().info):
            node.get_logger().error('Interrupted while waiting for the service. Exiting.')
            return 0
        future = client.call_async(AddTwoInts.Request(a=2, b=3))
        if spin_until_done(node, future, stop) and future.result() is not None:
            node.get_logger().info(f'Result of add_two_ints: {future.result().sum}')
        else:
            node.get_logger().error('Interrupted while waiting for response. Exiting.')
        node.destroy_node()
    return 0


if __name__ == '__main__':
    sys.exit(main())
