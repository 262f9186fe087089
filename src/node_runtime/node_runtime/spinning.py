"""Run a node until Ctrl-C or SIGTERM, then shut down cleanly with exit code 0.

rclpy's default Ctrl-C handling raises KeyboardInterrupt wherever the main thread happens
to be. When that is inside rclpy's C++ code (taking a message, say), pybind11 turns it into
`RuntimeError: Unable to convert call argument ...` and the node dies with a traceback and
exit code 1 (seen about once in eight stops of the demo). Here the signal only sets a flag,
and the spin loop notices it within SIGNAL_CHECK_PERIOD.
"""

from __future__ import annotations

import signal
import threading
from collections.abc import Iterator
from contextlib import contextmanager

import rclpy
from node_runtime.discovery import announce_often
from rclpy.executors import Executor, ExternalShutdownException, SingleThreadedExecutor
from rclpy.impl.implementation_singleton import rclpy_implementation as _rclpy
from rclpy.node import Node
from rclpy.signals import SignalHandlerOptions

SIGNAL_CHECK_PERIOD = 0.1  # seconds: the longest a stop request waits to be noticed


@contextmanager
def ros_session(args: list[str] | None = None) -> Iterator[threading.Event]:
    """rclpy.init with our own SIGINT/SIGTERM handlers; yields the event they set."""
    stop = threading.Event()
    announce_often()  # met within 0.5 s by processes that missed its first announcements
    try:
        rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    except _rclpy.RCLError as error:
        # Bad --ros-args (an unknown log level, a malformed remap): rcl's reason in one line,
        # without its source locations, instead of a traceback; exit code 1.
        raise SystemExit(str(error).split(', at /')[0]) from None
    for signum in (signal.SIGINT, signal.SIGTERM):
        signal.signal(signum, lambda _signum, _frame: stop.set())
    try:
        yield stop
    except ExternalShutdownException:
        pass  # the context was shut down elsewhere: a normal way to end
    finally:
        rclpy.try_shutdown()


def spin_until_stopped(node: Node, stop: threading.Event,
                       executor: Executor | None = None) -> None:
    """Spin `node` until `stop` is set (by a signal) or the context is shut down."""
    executor = executor or SingleThreadedExecutor()
    executor.add_node(node)
    try:
        while not stop.is_set() and rclpy.ok():
            executor.spin_once(timeout_sec=SIGNAL_CHECK_PERIOD)
    finally:
        executor.shutdown(timeout_sec=1.0)
        node.destroy_node()
