"""What the verbs of `ros2 action` share."""

from __future__ import annotations

import argparse
from typing import Any

from ros2cli.verb_context import VerbContext


def query_graph(
    args: argparse.Namespace,
    detail: bool = False,
    action: str | None = None,
    *,
    context: VerbContext,
):
    """A graph snapshot; with `action`, waiting a little for that action to appear."""
    from ros2cli.graph import graph_source

    def has_action(graph) -> bool:
        return action in dict(graph.actions())

    with graph_source(not args.no_daemon, args.spin_time, context) as source:
        return source.graph(detail=detail, ready=has_action if action else None)


def absolute(name: str) -> str:
    return name if name.startswith('/') else '/' + name


# Upstream's ros2action.api names, for code written against ros2cli. `node` is any rclpy node
# (or upstream's NodeStrategy/DirectNode).

def get_action_names_and_types(*, node: Any) -> list[tuple[str, list[str]]]:
    """Every action `node` sees, with its types."""
    getter = getattr(node, 'get_action_names_and_types', None)
    if getter is not None:
        return getter()
    from rclpy.action import get_action_names_and_types as names_and_types
    return names_and_types(node)


def get_action_names(*, node: Any) -> list[str]:
    return [name for name, _ in get_action_names_and_types(node=node)]


def get_action_clients_and_servers(*, node: Any, action_name: str
                                   ) -> tuple[list[tuple[str, list[str]]],
                                              list[tuple[str, list[str]]]]:
    """([(client node, types)], [(server node, types)]) of an action; the name is expanded
    and checked as rclpy does (ValueError/InvalidTopicNameException when malformed)."""
    from rclpy.action import graph
    from rclpy.expand_topic_name import expand_topic_name
    from rclpy.validate_full_topic_name import validate_full_topic_name

    rclpy_node = getattr(node, 'node', node)  # DirectNode wraps the rclpy node
    expanded = expand_topic_name(action_name, rclpy_node.get_name(),
                                 rclpy_node.get_namespace())
    validate_full_topic_name(expanded)
    clients, servers = [], []
    for name, namespace in rclpy_node.get_node_names_and_namespaces():
        full = namespace.rstrip('/') + '/' + name
        for found, query in ((clients, graph.get_action_client_names_and_types_by_node),
                             (servers, graph.get_action_server_names_and_types_by_node)):
            found += [(full, types) for each, types in query(rclpy_node, name, namespace)
                      if each == expanded]
    return clients, servers
