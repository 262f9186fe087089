"""What `record` and `play` share: a node spun until Ctrl-C/SIGTERM, and the space key.

Signals only set an event that the spin loop checks every SIGNAL_CHECK_PERIOD, so a stop
never interrupts rclpy (or a file write) half-way: the bag is always closed properly.
"""

from __future__ import annotations

import os
import sys
import threading
from collections.abc import Callable, Iterator
from contextlib import ExitStack, contextmanager
from typing import Any

SIGNAL_CHECK_PERIOD = 0.1
# A recorder first meets the participants on this host, for at most one whole Fast DDS
# announcement period (3 s, as the daemon), then waits for their endpoints to arrive.
MEET_BOUND = 3.3
SETTLE_BOUND = 1.0
# Seconds a stopped recorder or player may take to end: closing a bag (compressing its last
# split, writing metadata) can outlast a node's 4 s budget, and a bag cut short loses data.
# A SIGTERM while stopping still ends it at once.
CLOSE_BUDGET = 60.0


@contextmanager
def ros_node(name: str, stop: threading.Event | None = None, use_sim_time: bool = False,
             meet: bool = False) -> Iterator[tuple[Any, threading.Event]]:
    """A node in its own context, with SIGINT/SIGTERM setting the yielded stop event;
    `use_sim_time`: its clock follows /clock (the node's `use_sim_time` parameter); `meet`:
    yielded once it has met the graph already there (bounded, MEET_BOUND + SETTLE_BOUND)."""
    import rclpy
    from node_runtime.spinning import stopping_on_signals
    from rclpy.context import Context
    from rclpy.parameter import Parameter
    from rclpy.signals import SignalHandlerOptions

    stop = stop or threading.Event()
    handlers = ExitStack()
    # Signal handlers can only be set from the main thread: elsewhere (rosbag2_py's
    # Recorder/Player run in a thread) cancel() sets the stop event. node_runtime's: a stop
    # has the shutdown budget, a SIGTERM while stopping ends the process at once.
    if threading.current_thread() is threading.main_thread():
        handlers.enter_context(stopping_on_signals(stop, CLOSE_BUDGET))
    overrides = [Parameter('use_sim_time', Parameter.Type.BOOL, True)] if use_sim_time else []

    def make() -> tuple[Any, Any]:
        context = Context()
        rclpy.init(args=[], context=context, signal_handler_options=SignalHandlerOptions.NO)
        return context, rclpy.create_node(name, context=context, parameter_overrides=overrides)

    if meet:
        # A fresh participant knows nothing yet, and the others sometimes answer it only at
        # their next announcement, 3 s later: the CLI node's way, a fresh participant when
        # it is not met at once, then until the endpoints known have stopped changing.
        from ros2cli.node.discovery import meet_graph_made, settle_graph
        context, node, _ = meet_graph_made(make, MEET_BOUND)
        settle_graph(node, SETTLE_BOUND)
    else:
        context, node = make()
    try:
        yield node, stop
    finally:
        node.destroy_node()
        rclpy.try_shutdown(context=context)
        handlers.close()


def make_executor(node: Any, events: bool = False) -> Any:
    """SingleThreadedExecutor, or rclpy's EventsExecutor (no Python wait-set per wake-up).

    rclpy 7.1.6's EventsExecutor fails ("null argument to internal routine") on callbacks
    that take the message info, so with it the reception time is read in the callback.
    """
    if events:
        from rclpy.experimental.events_executor import EventsExecutor
        executor = EventsExecutor(context=node.context)
    else:
        from rclpy.executors import SingleThreadedExecutor
        executor = SingleThreadedExecutor(context=node.context)
    executor.add_node(node)
    return executor


def spin_until(executor: Any, node: Any, done: Callable[[], bool]) -> None:
    import rclpy
    from rclpy.executors import ExternalShutdownException

    try:
        while not done() and rclpy.ok(context=node.context):
            executor.spin_once(timeout_sec=SIGNAL_CHECK_PERIOD)
    except ExternalShutdownException:
        pass


class SpaceKey:
    """Calls `on_space` when the space bar is pressed, when stdin is a terminal.

    The terminal is switched to cbreak mode (keys arrive unbuffered, no echo) and restored
    on close. Without a terminal (pipes, tests, launch) it does nothing.
    """

    def __init__(self, on_space: Callable[[], None]):
        self.on_space = on_space
        self.active = False
        self._saved: Any = None
        try:
            self.active = sys.stdin.isatty()
        except (AttributeError, ValueError):
            self.active = False

    def start(self) -> None:
        if not self.active:
            return
        import termios
        import tty

        fd = sys.stdin.fileno()
        try:
            self._saved = termios.tcgetattr(fd)
            tty.setcbreak(fd)
        except termios.error:
            self.active = False
            return
        threading.Thread(target=self._read, args=(fd,), daemon=True).start()

    def _read(self, fd: int) -> None:
        while self.active:
            try:
                key = os.read(fd, 1)
            except OSError:
                return
            if not key:
                return
            if key == b' ':
                self.on_space()

    def close(self) -> None:
        if self._saved is not None:
            import termios
            try:
                termios.tcsetattr(sys.stdin.fileno(), termios.TCSADRAIN, self._saved)
            except termios.error:
                pass
            self._saved = None
        self.active = False
