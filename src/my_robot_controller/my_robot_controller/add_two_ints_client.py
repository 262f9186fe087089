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
        # Spun while waiting too, so that its parameter services answer (`ros2 param list
        # /add_two_ints_client` would otherwise wait for a node that never replies).
        self.spinner = SingleThreadedExecutor()
        self.spinner.add_node(self)

    def wait_for_server(self, stop: threading.Event) -> bool:
        """Wait until the server is there (True) or a signal asks us to stop (False).

        Short spins, so that Ctrl-C or SIGTERM is noticed within SIGNAL_CHECK_PERIOD while the
        context is still valid (rclpy's own handler shut the context down under a waiting
        wait_for_service: `RCLError: ... context is invalid` and exit code 1).
        """
        next_warning = time.monotonic() + WAIT_WARN_PERIOD
        while not stop.is_set():
            if self.client.service_is_ready():
                return True
            self.spinner.spin_once(timeout_sec=SIGNAL_CHECK_PERIOD)
            if time.monotonic() >= next_warning:
                next_warning += WAIT_WARN_PERIOD
                self.get_logger().warning('service /add_two_ints not available, waiting again...')
        return False

    def add(self, a: int, b: int, stop: threading.Event) -> int | None:
        """The sum from the server, or None when stopped by a signal before the answer."""
        future = self.client.call_async(AddTwoInts.Request(a=a, b=b))
        while not future.done() and not stop.is_set():
            self.spinner.spin_once(timeout_sec=SIGNAL_CHECK_PERIOD)
        return future.result().sum if future.done() else None

    def close(self) -> None:
        self.spinner.shutdown(timeout_sec=1.0)
        self.destroy_node()


def main(args: list[str] | None = None) -> int:
    argv = remove_ros_args(sys.argv if args is None else args)[1:]
    try:
        a, b = parse_operands(argv)
    except ArgumentError as error:
        print(f'add_two_ints_client: error: {error}\n{USAGE}', file=sys.stderr)
        return 2
    with ros_session(args) as stop:
        node = AddTwoIntsClient()
        try:
            total = node.add(a, b, stop) if node.wait_for_server(stop) else None
            if total is not None:
                node.get_logger().info(f'Result of add_two_ints: {a} + {b} = {total}')
        finally:
            node.close()
    # Interrupted before the answer: 130, as a shell reports Ctrl-C.
    return 130 if total is None else 0


if __name__ == '__main__':
    sys.exit(main())
