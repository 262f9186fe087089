"""`ros2 run demo_nodes_py add_two_ints_server`: serves /add_two_ints (AddTwoInts)."""
import sys

from example_interfaces.srv import AddTwoInts
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.node import Node


class AddTwoIntsServer(Node):
    def __init__(self, name: str = 'add_two_ints_server') -> None:
        super().__init__(name)
        self.srv = self.create_service(AddTwoInts, 'add_two_ints', self.on_request)

    def on_request(self, request: AddTwoInts.Request,
                   response: AddTwoInts.Response) -> AddTwoInts.Response:
        # The sum of two int64 wraps around in C++; a Python int would not fit the field.
        response.sum = (request.a + request.b + 2**63) % 2**64 - 2**63
        self.get_logger().info(f'Incoming request\na: {request.a} b: {request.b}')
        return response


def main() -> int:
    with ros_session() as stop:
        spin_until_stopped(AddTwoIntsServer(), stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
