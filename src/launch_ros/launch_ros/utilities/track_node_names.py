"""How many nodes of each fully qualified name a launch started (to warn about duplicates)."""

from __future__ import annotations

from typing import Any

_KEY = 'unique_ros_node_names'  # the launch context's global, as upstream


def _counts(context: Any) -> dict[str, int]:
    if not hasattr(context.locals, _KEY):
        # launch's globals outlive a scope; a launch without them keeps the dict in the
        # outermost locals, which every scope copies by reference.
        extend = getattr(context, 'extend_globals', context.extend_locals)
        extend({_KEY: {}})
    return getattr(context.locals, _KEY)


def add_node_name(context: Any, node_name: str) -> None:
    counts = _counts(context)
    counts[node_name] = counts.get(node_name, 0) + 1


def get_node_name_count(context: Any, node_name: str) -> int:
    return _counts(context).get(node_name, 0)
