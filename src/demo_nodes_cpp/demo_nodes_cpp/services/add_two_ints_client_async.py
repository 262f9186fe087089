"""`ros2 run demo_nodes_cpp add_two_ints_client_async`: the request's answer is logged in a
callback, which then shuts the process down."""
import sys

from demo_nodes_py.services.client_wait import spin_until, wait_for_service
from example_interfaces.srv import AddTwoInts
from node_runtime.spinning import ros_session
from rclpy.node import Node
from rclpy.task import Future


class ClientNode(Node):
    def __init__(self) -> None:
        super().__init__('add_two_ints_client')
        self.client = self.create_client(AddTwoInts, 'add_two_ints')
        self.answered = False

    def on_answer(self, future: Future) -> None:
        self.answered = True  # upstream's callback shuts the process down
        if future.result() is not None:
            self.get_logger().info(f'Result of add_two_ints: {future.result().sum}')


def main() -> int:
    with ros_session() as stop:
        node = ClientNode()
        if not wait_for_service(node.client, stop, node.get_logger().info):
            node.get_logger().error('Interrupted while waiting for the service. Exiting.')
            return 0
        future = node.client.call_async(AddTwoInts.Request(a=2, b=3))
        future.add_done_callback(node.on_answer)
        spin_until(node, lambda: node.answered, stop)
        node.destroy_node()
    return 0


if __name__ == '__main__':
    sys.exit(main())
