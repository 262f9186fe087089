"""matches_node_name: an event matcher for the Node action of one fully qualified name."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


def matches_node_name(node_name: str) -> Callable[[Any], bool]:
    """Matches a Node whose name is `node_name` ('/' added in front when missing)."""
    if not node_name.startswith('/'):
        node_name = f'/{node_name}'
    return lambda action: getattr(action, 'node_name', None) == node_name
