"""What the verbs of `ros2 lifecycle` share: finding managed nodes and calling their services.

A managed node is one that serves `<node>/get_state` of type lifecycle_msgs/srv/GetState
(as ros2lifecycle decides).
"""

from __future__ import annotations

import argparse
import time
from typing import Any

from ros2cli.verb_context import VerbContext

GET_STATE_TYPE = 'lifecycle_msgs/srv/GetState'
CALL_TIMEOUT = 5.0  # seconds: a listed node that never answers fails instead of hanging


def add_node_name(parser: argparse.ArgumentParser, optional: bool = False) -> None:
    if optional:
        parser.add_argument('node_name', nargs='?', help='Name of the ROS node. If no name is '
                            'provided, then get the state for all nodes.')
    else:
        parser.add_argument('node_name', help='Name of the ROS node')
    parser.add_argument('--include-hidden-nodes', action='store_true',
                        help='Consider hidden nodes as well')


def absolute(name: str | None) -> str | None:
    if not name:
        return None
    return name if name.startswith('/') else '/' + name


def _managed(graph: Any, include_hidden: bool) -> list[str]:
    servers = {name for name, types in graph.services(include_hidden=True)
               if GET_STATE_TYPE in types}
    return sorted({name for name in graph.node_names(include_hidden)
                   if f'{name}/get_state' in servers})


def managed_node_names(args: argparse.Namespace, include_hidden: bool,
                       wanted: str | None = None, *, context: VerbContext) -> list[str]:
    """Full names of the managed nodes; with `wanted`, wait (within the lookup bound) for it."""
    from ros2cli.graph import graph_source
    with graph_source(not args.no_daemon, args.spin_time, context) as source:
        graph = source.graph(ready=None if wanted is None
                             else lambda g: wanted in _managed(g, include_hidden))
    return _managed(graph, include_hidden)


def call(node: Any, srv_type: Any, service: str, request: Any, context: VerbContext) -> Any:
    """The node's answer, or the exception to report ('Exception while calling service...')."""
    from ros2cli.node.direct import spin_once
    client = node.create_client(srv_type, service)
    if not client.wait_for_service(timeout_sec=CALL_TIMEOUT):
        return TimeoutError(f"service '{service}' not available")
    future = client.call_async(request)
    deadline = time.monotonic() + CALL_TIMEOUT
    while not future.done():
        if time.monotonic() > deadline:
            client.remove_pending_request(future)
            return TimeoutError(f"service '{service}' did not answer within "
                                f'{CALL_TIMEOUT:g} s')
        spin_once(node, 0.1, context)
    if future.exception() is not None:
        return future.exception()
    return future.result()


def transitions(node: Any, node_name: str, graph: bool = False, *, context: VerbContext) -> Any:
    """The node's available transitions (with `graph`, its whole transition graph)."""
    from lifecycle_msgs.srv import GetAvailableTransitions
    service = 'get_transition_graph' if graph else 'get_available_transitions'
    result = call(node, GetAvailableTransitions, f'{node_name}/{service}',
                  GetAvailableTransitions.Request(), context=context)
    return result if isinstance(result, Exception) else list(result.available_transitions)


def exception_text(node_name: str, error: Exception) -> str:
    return f"Exception while calling service of node '{node_name}': {error}"
