"""ros2node's API: upstream's ros2node.api names (node names as NodeName tuples, the duplicate
name check and its warning) for code written against ros2cli; the `ros2 node` verbs use them.

`node` is any rclpy node (or upstream's NodeStrategy/DirectNode, which answer the same
graph queries).
"""

from __future__ import annotations

from typing import Any, NamedTuple

# The warning of `ros2 node info` when several nodes share the name asked for (upstream's).
INFO_NONUNIQUE_WARNING_TEMPLATE = (
    'There are {num_nodes} nodes in the graph with the exact name "{node_name}". '
    'You are seeing information about only one of them.')


class NodeName(NamedTuple):
    name: str
    namespace: str
    full_name: str


def get_absolute_node_name(node_name: str | None) -> str | None:
    """`node_name` with a leading '/'; None for no name."""
    if not node_name:
        return None
    return node_name if node_name.startswith('/') else '/' + node_name


def parse_node_name(node_name: str) -> NodeName:
    """A node name, with or without its leading '/', split into name and namespace."""
    full_name = get_absolute_node_name(node_name) or '/'
    namespace, name = full_name.rsplit('/', 1)
    return NodeName(name, namespace or '/', full_name)


def has_duplicates(values: list[Any]) -> bool:
    """Whether any value occurs more than once."""
    return len(set(values)) < len(values)


def get_node_names(*, node: Any, include_hidden_nodes: bool = False) -> list[NodeName]:
    """Every node `node` sees (hidden ones, named `_...`, only when asked), duplicates kept."""
    return [NodeName(name, namespace, namespace.rstrip('/') + '/' + name)
            for name, namespace in node.get_node_names_and_namespaces()
            if include_hidden_nodes or (name and not name.startswith('_'))]
