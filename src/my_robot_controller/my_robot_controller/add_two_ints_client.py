"""Ask /add_two_ints for the sum of two integers (default 3 and 4) and log it."""

import sys

import rclpy
from example_interfaces.srv import AddTwoInts
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.utilities import remove_ros_args

from my_robot_controller.int64 import INT64_RANGE, fits_int64

USAGE = 'usage: ros2 run my_robot_controller add_two_ints_client [a b]'
DEFAULT_A, DEFAULT_B = 3, 4


class ArgumentError(ValueError):
    pass


def parse_operands(argv: list[str]) -> tuple[int, int]:
    """Return (a, b) from the non-ROS arguments, or raise ArgumentError naming the bad one."""
    if not argv:
        return DEFAULT_A, DEFAULT_B
    if len(argv) != 2:
        raise ArgumentError(f'expected two integers a and b, got {len(argv)} argument(s)')
    operands = []
    for name, text in zip('ab', argv, strict=True):
        try:
            value = int(text, 10)
        except ValueError:
            raise ArgumentError(
                f"argument '{name}' must be an integer in {INT64_RANGE}, got '{text}'") from None
        if not fits_int64(value):
            raise ArgumentError(f"argument '{name}' = {value} is outside int64 {INT64_RANGE}")
        operands.append(value)
    a, b = operands
    if not fits_int64(a + b):
        raise ArgumentError(f'the sum {a} + {b} = {a + b} would overflow int64 {INT64_RANGE}')
    return a, b


class AddTwoIntsClient(Node):
    def __init__(self) -> None:
        super().__init__('add_two_ints_client')
        self.client = self.create_client(AddTwoInts, 'add_two_ints')

    def wait_for_server(self) -> None:
        while not self.client.wait_for_service(timeout_sec=1.0):
            self.get_logger().warning('service /add_two_ints not available, waiting again...')

    def add(self, a: int, b: int) -> int:
        future = self.client.call_async(AddTwoInts.Request(a=a, b=b))
        rclpy.spin_until_future_complete(self, future)
        return future.result().sum


def main(args: list[str] | None = None) -> int:
    argv = remove_ros_args(sys.argv if args is None else args)[1:]
    try:
        a, b = parse_operands(argv)
    except ArgumentError as error:
        print(f'add_two_ints_client: error: {error}\n{USAGE}', file=sys.stderr)
        return 2
    try:
        rclpy.init(args=args)
        node = AddTwoIntsClient()
        node.wait_for_server()
        total = node.add(a, b)
        node.get_logger().info(f'Result of add_two_ints: {a} + {b} = {total}')
    except (KeyboardInterrupt, ExternalShutdownException):
        return 130
    finally:
        rclpy.try_shutdown()
    return 0


if __name__ == '__main__':
    sys.exit(main())
