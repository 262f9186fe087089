"""Ask /add_two_ints for the sum of two integers (default 3 and 4) and log it."""

import sys
import threading
import time

from example_interfaces.srv import AddTwoInts
from node_runtime.spinning import SIGNAL_CHECK_PERIOD, ros_session
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.utilities import remove_ros_args

from my_robot_controller.int64 import INT64_RANGE, fits_int64

USAGE = 'usage: ros2 run my_robot_controller add_two_ints_client [a b]'
DEFAULT_A, DEFAULT_B = 3, 4
WAIT_WARN_PERIOD = 1.0  # seconds between two "not available" lines, as upstream


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

    def wait_for_server(self, stop: threading.Event) -> bool:
        """Wait until the server is there (True) or a signal asks us to stop (False).

        Short waits, so that Ctrl-C or SIGTERM is noticed within SIGNAL_CHECK_PERIOD while the
        context is still valid (rclpy's own handler shut the context down under a waiting
        wait_for_service: `RCLError: ... context is invalid` and exit code 1).
        """
        next_warning = time.monotonic() + WAIT_WARN_PERIOD
        while not stop.is_set():
            if self.client.wait_for_service(timeout_sec=SIGNAL_CHECK_PERIOD):
                return True
            if time.monotonic() >= next_warning:
                next_warning += WAIT_WARN_PERIOD
                self.get_logger().warning('service /add_two_ints not available, waiting again...')
        return False

    def add(self, a: int, b: int, stop: threading.Event) -> int | None:
        """The sum from the server, or None when stopped by a signal before the answer."""
        future = self.client.call_async(AddTwoInts.Request(a=a, b=b))
        executor = SingleThreadedExecutor()
        executor.add_node(self)
        try:
            while not future.done() and not stop.is_set():
                executor.spin_once(timeout_sec=SIGNAL_CHECK_PERIOD)
        finally:
            executor.remove_node(self)
            executor.shutdown(timeout_sec=1.0)
        return future.result().sum if future.done() else None


def main(args: list[str] | None = None) -> int:
    argv = remove_ros_args(sys.argv if args is None else args)[1:]
    try:
        a, b = parse_operands(argv)
    except ArgumentError as error:
        print(f'add_two_ints_client: error: {error}\n{USAGE}', file=sys.stderr)
        return 2
    with ros_session(args) as stop:
        node = AddTwoIntsClient()
        total = node.add(a, b, stop) if node.wait_for_server(stop) else None
        if total is None:
            return 130  # interrupted before the answer (as a shell reports Ctrl-C)
        node.get_logger().info(f'Result of add_two_ints: {a} + {b} = {total}')
    return 0


if __name__ == '__main__':
    sys.exit(main())
