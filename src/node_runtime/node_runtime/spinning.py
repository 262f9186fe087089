"""Run a node until Ctrl-C or SIGTERM, then shut down cleanly with exit code 0.

rclpy's default Ctrl-C handling raises KeyboardInterrupt wherever the main thread happens
to be. When that is inside rclpy's C++ code (taking a message, say), pybind11 turns it into
`RuntimeError: Unable to convert call argument ...` and the node dies with a traceback and
exit code 1 (seen about once in eight stops of the demo). Here the signal only sets a flag,
and the spin loop notices it within SIGNAL_CHECK_PERIOD.

Once stopping, the process ends within SHUTDOWN_BUDGET whatever its threads are doing. A
Python signal handler runs only when the main thread is between two bytecodes: a main thread
held inside rclpy's C++ code (destroying a node, shutting down the context) never runs one, and
such a node once outlived its launch, deaf to SIGINT and SIGTERM. faulthandler's watchdog is a
thread below Python (it needs no GIL): from the first stop request on, it ends the process
after SHUTDOWN_BUDGET seconds, printing where each thread was, so that the hang can be found.
A SIGTERM while stopping ends the process at once when Python gets to run its handler.
"""

from __future__ import annotations

import faulthandler
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
# Seconds from the first Ctrl-C or SIGTERM to the end of the process. Below launch's
# sigterm_timeout (5 s), so that launch never has to escalate: a clean stop takes 0.1-1 s.
SHUTDOWN_BUDGET = 4.0
# A node's executor gets this long to let running callbacks finish (within the budget).
EXECUTOR_SHUTDOWN_TIMEOUT = 1.0


def limit_shutdown(budget: float = SHUTDOWN_BUDGET) -> None:
    """From now on, end the process within `budget` seconds (calling it again restarts it)."""
    # exit=True: _exit(1) after printing every thread's stack on stderr (which launch logs).
    faulthandler.dump_traceback_later(budget, exit=True)


def stop_on_signals(stop: threading.Event, budget: float = SHUTDOWN_BUDGET) -> None:
    """SIGINT and SIGTERM set `stop` and start the shutdown `budget`; a SIGTERM while stopping
    ends the process at once (a second SIGINT does nothing, as in rclcpp)."""
    def on_signal(signum: int, _frame: object) -> None:
        if not stop.is_set():
            stop.set()
            limit_shutdown(budget)
        elif signum == signal.SIGTERM:
            faulthandler.dump_traceback(all_threads=True)  # where the shutdown was
            signal.signal(signal.SIGTERM, signal.SIG_DFL)
            signal.raise_signal(signal.SIGTERM)

    for signum in (signal.SIGINT, signal.SIGTERM):
        signal.signal(signum, on_signal)


@contextmanager
def stopping_on_signals(stop: threading.Event,
                        budget: float = SHUTDOWN_BUDGET) -> Iterator[None]:
    """stop_on_signals for a while only: for a session inside a process that goes on after
    it (rosbag2_py's record()/play(), called from a script's main thread). On leaving, the
    previous handlers come back and the shutdown budget of a stop is called off."""
    previous = {signum: signal.getsignal(signum) for signum in (signal.SIGINT, signal.SIGTERM)}
    stop_on_signals(stop, budget)
    try:
        yield
    finally:
        faulthandler.cancel_dump_traceback_later()
        for signum, handler in previous.items():
            signal.signal(signum, handler)


@contextmanager
def ros_session(args: list[str] | None = None) -> Iterator[threading.Event]:
    """rclpy.init with our own SIGINT/SIGTERM handlers; yields the event they set."""
    stop = threading.Event()
    # Before rclpy.init: a KeyboardInterrupt raised inside rclpy's C++ calls can be lost, and
    # a node Ctrl-C'd while it starts would run on until launch's SIGTERM 5 s later.
    stop_on_signals(stop)
    announce_often()  # met within 0.5 s by processes that missed its first announcements
    try:
        rclpy.init(args=args, signal_handler_options=SignalHandlerOptions.NO)
    except _rclpy.RCLError as error:
        # Bad --ros-args (an unknown log level, a malformed remap): rcl's reason in one line,
        # without its source locations, instead of a traceback; exit code 1.
        raise SystemExit(str(error).split(', at /')[0]) from None
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
        executor.shutdown(timeout_sec=EXECUTOR_SHUTDOWN_TIMEOUT)
        node.destroy_node()
