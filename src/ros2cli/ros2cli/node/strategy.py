"""NodeStrategy: the daemon when one runs, else a direct node (starting the daemon for next time).

Third-party `ros2` tools write `with NodeStrategy(args) as node: node.get_topic_names_and_types()`
and call `add_arguments(parser)` for --spin-time, --use-sim-time and --no-daemon; this is that
API on ros2cli's daemon (see ros2cli.node.daemon) and DirectNode.
"""

from __future__ import annotations

import argparse
from typing import Any

from ros2cli.node.daemon import DaemonNode, is_daemon_running, spawn_daemon
from ros2cli.node.daemon import add_arguments as add_daemon_node_arguments
from ros2cli.node.direct import DirectNode
from ros2cli.node.direct import add_arguments as add_direct_node_arguments


class NodeStrategy:
    """Graph queries go to the daemon when it answers them, else to a node of our own."""

    def __init__(self, args: Any) -> None:
        use_daemon = not getattr(args, 'no_daemon', False)
        self._daemon_node: DaemonNode | None = None
        self._direct_node: DirectNode | None = None
        if use_daemon and is_daemon_running(args):
            daemon = DaemonNode(args)
            if daemon.connected:
                self._daemon_node = daemon
            else:  # it went away in between
                self._direct_node = DirectNode(args)
        else:
            if use_daemon:
                spawn_daemon(args)  # for the next command; this one discovers by itself
            self._direct_node = DirectNode(args)
        self._args = args
        self._in_scope = False

    @property
    def daemon_node(self) -> DaemonNode | None:
        return self._daemon_node

    @property
    def direct_node(self) -> DirectNode:
        """The node of our own, made on first use (e.g. to create a subscription)."""
        if self._direct_node is None:
            self._direct_node = DirectNode(self._args)
            if self._in_scope:
                self._direct_node.__enter__()
        return self._direct_node

    def __enter__(self) -> NodeStrategy:
        for node in (self._daemon_node, self._direct_node):
            if node is not None:
                node.__enter__()
        self._in_scope = True
        return self

    def __getattr__(self, name: str) -> Any:
        if name.startswith('_'):  # never recurse while __init__ has not set them yet
            raise AttributeError(name)
        if self._daemon_node is not None and name in self._daemon_node.methods:
            return getattr(self._daemon_node, name)
        return getattr(self.direct_node, name)

    def __exit__(self, exc_type: Any, exc_value: Any, traceback: Any) -> None:
        self._in_scope = False
        for node in (self._direct_node, self._daemon_node):
            if node is not None:
                node.__exit__(exc_type, exc_value, traceback)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_daemon_node_arguments(parser)
    add_direct_node_arguments(parser)
    parser.add_argument('--no-daemon', action='store_true',
                        help='Do not spawn nor use an already running daemon')
