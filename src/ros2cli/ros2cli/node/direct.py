"""DirectNode: a tool's own node in rclpy's default context, met with the graph first."""

from __future__ import annotations

import argparse
import os
import time
from typing import Any

from ros2cli.node import NODE_NAME_PREFIX

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
        from ros2cli_lite.node import wait_for_graph, wait_until
        from ros2cli_lite.participants import everyone_met

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
