"""`ros2 run demo_nodes_py add_two_ints_client_async`: the client with the answer taken in a
done callback while the node spins."""
import sys

import rclpy
from example_interfaces.srv import AddTwoInts
from node_runtime.spinning import ros_session
from rclpy.task import Future

from demo_nodes_py.services.client_wait import spin_until, wait_for_service


def main() -> int:
    with ros_session() as stop:
        node = rclpy.create_node('add_two_ints_client')
        cli = node.create_client(AddTwoInts, 'add_two_ints')
        answered = []

        def on_answer(future: Future) -> None:
            answered.append(future)
            if future.result() is not None:
                node.get_logger().info(f'Result of add_two_ints: {future.result().sum}')
            else:
                node.get_logger().error(f'Exception while calling service: {future.exception()!r}')

        if wait_for_service(cli, stop):
            future = cli.call_async(AddTwoInts.Request(a=2, b=3))
            future.add_done_callback(on_answer)
            spin_until(node, lambda: bool(answered), stop)
        node.destroy_node()
    return 0


if __name__ == '__main__':
    sys.exit(main())
