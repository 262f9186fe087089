"""What the verbs of `ros2 action` share."""

from __future__ import annotations

import argparse


def query_graph(args: argparse.Namespace, detail: bool = False, action: str | None = None):
    """A graph snapshot; with `action`, waiting a little for that action to appear."""
    from ros2cli.graph import graph_source

    def has_action(graph) -> bool:
        return action in dict(graph.actions())
    with graph_source(not args.no_daemon, args.spin_time) as source:
        return source.graph(detail=detail, ready=has_action if action else None)


def absolute(name: str) -> str:
    return name if name.startswith('/') else '/' + name
