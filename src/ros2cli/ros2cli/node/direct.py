"""The CLI's own node (ros2cli's direct node): made, met with the graph, spun, torn down.

A verb that talks to the graph itself (echo, pub, call, param get, ...) opens one with
`cli_node()`; DirectNode is upstream's class of the same, for third-party tools.
"""

from __future__ import annotations

import argparse
import os
import time
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from ros2cli.node import NODE_NAME_PREFIX
from ros2cli.node.discovery import create_node, make_node, meet_graph_replacing
from ros2cli.verb_context import VerbContext


@contextmanager
def cli_node(context: VerbContext, name: str | None = None, discover: bool = True,
             spin_time: float | None = None) -> Iterator[Any]:
    """A hidden node `_ros2cli_<pid>` for the verb running in `context`, torn down on exit.

    In the CLI: a node in a fresh rclpy context; with `discover`, it has met the rest of the
    graph first (see meet_graph_replacing), for at most `spin_time` seconds when given (a
    verb's --spin-time). In the daemon (`context.in_daemon`): a node of the daemon's
    participant, which knows the graph already.
    """
    import rclpy

    node_name = name or f'{NODE_NAME_PREFIX}_{context.pid}'
    if context.in_daemon:
        ros_context = context.ros_context
        node = create_node(node_name, ros_context)
    else:
        ros_context, node = make_node(node_name)
    try:
        if discover and not context.in_daemon:
            bound = 1.8 if spin_time is None else min(1.8, spin_time)
            ros_context, node, _ = meet_graph_replacing(
                ros_context, node, lambda: make_node(node_name), bound=bound)
        yield node
    finally:
        # Shut the executor of spin_once down while its context lives: left to the garbage
        # collector, it would destroy its guard condition after the context and print
        # "Exception ignored in: Executor.__del__ ... InvalidHandle" on stderr.
        executor = getattr(node, '_cli_executor', None)
        if executor is not None:
            executor.shutdown(timeout_sec=1.0)
        node.destroy_node()
        if not context.in_daemon:
            rclpy.try_shutdown(context=ros_context)


def spin_once(node: Any, timeout: float, context: VerbContext | None = None) -> None:
    """Process pending callbacks of `node` for at most `timeout` seconds; first, in a verb the
    daemon runs, end it (KeyboardInterrupt) when its CLI has left."""
    if context is not None:
        context.check_cancelled()
    executor = getattr(node, '_cli_executor', None)
    if executor is None:
        executor = _cli_executor_class()(context=node.context)
        executor.add_node(node)
        node._cli_executor = executor
    executor.spin_once(timeout_sec=timeout)


def _cli_executor_class() -> type:
    from rclpy.executors import SingleThreadedExecutor

    class CliExecutor(SingleThreadedExecutor):
        """rclpy's executor, quiet when a Ctrl-C cut its __init__ short.

        rclpy's __del__ then reads an attribute __init__ never set and prints "Exception
        ignored ... no attribute '_sigint_gc'" (found by tests/test_clean_exits.py).
        """

        def __del__(self) -> None:
            if hasattr(self, '_sigint_gc'):
                super().__del__()

    return CliExecutor


# Seconds a fresh node may wait for discovery (--spin-time), as upstream.
DEFAULT_TIMEOUT = 0.5


class DirectNode:
    """A hidden node `_ros2cli_<pid>` (or `node_name`), usable as a context manager.

    Attributes it lacks come from the rclpy node (`self.node`), as upstream's: a tool calls
    `get_topic_names_and_types()` and friends on it directly. rclpy is initialised in the
    default context (and shut down on exit) so the tool can spin the node with rclpy's
    global executor.
    """

    def __init__(self, args: Any, *, node_name: str | None = None) -> None:
        import rclpy
        from rclpy.parameter import Parameter

        from ros2cli.node.discovery import wait_for_graph, wait_until
        from ros2cli.node.participants import everyone_met

        rclpy.init(args=getattr(args, 'argv', []))
        if node_name is None:
            node_name = NODE_NAME_PREFIX + getattr(args, 'node_name_suffix', f'_{os.getpid()}')
        self.node = rclpy.create_node(
            node_name,
            start_parameter_services=getattr(args, 'start_parameter_services', False),
            parameter_overrides=[
                Parameter('use_sim_time', value=getattr(args, 'use_sim_time', False)),
                Parameter('start_type_description_service',
                          value=getattr(args, 'start_type_description_service', True)),
            ],
            automatically_declare_parameters_from_overrides=True)
        # A fresh participant knows nothing yet: let discovery run for at most --spin-time,
        # returning once every participant on this host is known and the graph has settled
        # (knowing some other node is not enough: that may be the daemon just spawned).
        bound = getattr(args, 'spin_time', DEFAULT_TIMEOUT)
        start = time.monotonic()
        met = wait_until(lambda: everyone_met(self.node) is not False, bound)
        wait_for_graph(self.node, bound=max(0.0, bound - (time.monotonic() - start)),
                       everyone_met=met and everyone_met(self.node) is not None)

    def __enter__(self) -> DirectNode:
        return self

    # rclpy keeps the action graph queries in rclpy.action, not on the node.
    def get_action_names_and_types(self) -> list[tuple[str, list[str]]]:
        import rclpy.action
        return rclpy.action.get_action_names_and_types(self.node)

    def get_action_client_names_and_types_by_node(self, remote_node_name: str,
                                                  remote_node_namespace: str) -> list:
        import rclpy.action
        return rclpy.action.get_action_client_names_and_types_by_node(
            self.node, remote_node_name, remote_node_namespace)

    def get_action_server_names_and_types_by_node(self, remote_node_name: str,
                                                  remote_node_namespace: str) -> list:
        import rclpy.action
        return rclpy.action.get_action_server_names_and_types_by_node(
            self.node, remote_node_name, remote_node_namespace)

    def __getattr__(self, name: str) -> Any:
        import rclpy
        if not rclpy.ok():
            raise RuntimeError('!rclpy.ok()')
        return getattr(self.node, name)

    def __exit__(self, exc_type: Any, exc_value: Any, traceback: Any) -> None:
        import rclpy
        self.node.destroy_node()
        rclpy.try_shutdown()


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        '--spin-time', type=float, default=DEFAULT_TIMEOUT,
        help='Spin time in seconds to wait for discovery (only applies when not using an '
             'already running daemon)')
    parser.add_argument('-s', '--use-sim-time', action='store_true',
                        help='Enable ROS simulation time')
