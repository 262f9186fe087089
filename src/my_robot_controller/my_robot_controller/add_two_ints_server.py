"""Serve /add_two_ints: answer each request with the sum of its two integers."""

from example_interfaces.srv import AddTwoInts
from rclpy.node import Node

from my_robot_controller.int64 import INT64_RANGE, fits_int64
from my_robot_controller.spinning import ros_session, spin_until_stopped


class AddTwoIntsServer(Node):
    def __init__(self) -> None:
        super().__init__('add_two_ints_server')
        self.create_service(AddTwoInts, 'add_two_ints', self.on_add_two_ints)
        self.get_logger().info('Ready to add two ints on /add_two_ints')

    def on_add_two_ints(self, request: AddTwoInts.Request,
                        response: AddTwoInts.Response) -> AddTwoInts.Response:
        total = request.a + request.b
        self.get_logger().info(f'Incoming request: a={request.a} b={request.b}')
        if not fits_int64(total):
            # The interface has no error field: answer 0 and say why, never crash.
            self.get_logger().error(
                f'sum {request.a} + {request.b} = {total} does not fit in int64 '
                f'{INT64_RANGE}; answering sum=0')
            response.sum = 0
            return response
        response.sum = total
        self.get_logger().info(f'Sending back sum={total}')
        return response


def main(args: list[str] | None = None) -> None:
    with ros_session(args) as stop:
        spin_until_stopped(AddTwoIntsServer(), stop)


if __name__ == '__main__':
    main()
