"""What the commands share to build their parsers: the options every graph verb has.

A command is a module named by an ament index resource `ros2cli.command/<name>` (see
ros2cli/cli.py) with add_arguments(parser), which adds one sub-parser per verb module of its
package (`<package>.verb.<verb>`) and sets `_main` to the verb's main.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


def add_graph_verb(verbs: Any, name: str, func: Callable, help_text: str,
                   hidden_flag: str | None = None, hidden_dest: str | None = None) -> Any:
    """A verb parser with the options every graph verb shares (as ros2cli's verbs do)."""
    import argparse

    parser = verbs.add_parser(name, help=help_text, description=help_text)
    if hidden_flag:  # also accepted after the verb, as ros2cli does
        parser.add_argument(hidden_flag, action='store_true', dest=hidden_dest,
                            help=argparse.SUPPRESS)
    # `--spin-time S` (ros2cli's discovery time without a daemon) bounds the discovery waits:
    # each verb passes args.spin_time on (cli_node, graph_source, wait_for_graph).
    parser.add_argument('--spin-time', type=_non_negative_seconds, default=None,
                        help='Longest wait in seconds for a named entity to appear (default: '
                        '1 with the daemon; with --no-daemon the discovery time: 2 to list, 4 '
                        'to find)')
    parser.add_argument('-s', '--use-sim-time', action='store_true', help=argparse.SUPPRESS)
    parser.add_argument('--no-daemon', action='store_true',
                        help='Do not spawn nor use an already running daemon')
    parser.set_defaults(_main=func)
    return parser


def _non_negative_seconds(text: str) -> float:
    return max(0.0, float(text))
