"""matches_node_name: the lifecycle_node_matcher of a ChangeState for one node."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


def matches_node_name(node_name: str) -> Callable[[Any], bool]:
    """True for the LifecycleNode action whose node is `node_name` ('/' added if missing)."""
    full = node_name if node_name.startswith('/') else '/' + node_name
    return lambda action: action.node_name == full
