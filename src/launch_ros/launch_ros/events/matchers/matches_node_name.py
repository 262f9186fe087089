"""matches_node_name: a matcher of the node actions (Node, LifecycleNode) named so."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


def matches_node_name(node_name: str) -> Callable[[Any], bool]:
    """True for the action whose node is `node_name` ('/' added if missing)."""
    full = node_name if node_name.startswith('/') else '/' + node_name
    return lambda action: action.node_name == full
