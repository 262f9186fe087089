"""What every command shares: the error a verb raises, graph names, the graph verbs' common
options, interface types.

The CLI node and graph waits are in ros2cli_lite.node; message <-> YAML conversion is
rosidl_runtime_py's (ros2cli_lite.convert adds the command line's YAML parsing). Heavy
modules (rclpy, yaml, the generated interfaces) are imported inside the functions that need
them, so `ros2 interface show` or `ros2 run` never pay for DDS.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


class CliError(Exception):
    """A verb failed: the message goes to stderr and `ros2` exits with 1."""


def is_hidden(name: str) -> bool:
    """A topic/service name is hidden when any of its `/` tokens starts with `_`."""
    return any(token.startswith('_') for token in name.split('/'))


def is_hidden_node(name: str) -> bool:
    return name.startswith('_')


def print_names(names: list[str], count_only: bool) -> None:
    """One name a line, or with `count_only` (the `-c` of list/find verbs) just how many."""
    if count_only:
        print(len(names))
    else:
        for name in names:
            print(name)


def full_node_name(name: str, namespace: str) -> str:
    return namespace.rstrip('/') + '/' + name


# --------------------------------------------------------------------------------------
# The options every graph verb shares
# --------------------------------------------------------------------------------------

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


# --------------------------------------------------------------------------------------
# Interface types
# --------------------------------------------------------------------------------------

def import_type(name: str, kind: str) -> Any:
    """The generated class 'pkg/kind/Name' or 'pkg/Name' names (kind = msg, srv or action;
    also a service's parts, e.g. 'pkg/srv/Name_Event'); ValueError(name) for anything else."""
    from rosidl_runtime_py.utilities import get_interface

    parts = name.split('/')
    if len(parts) == 2:
        parts = [parts[0], kind, parts[1]]
    if len(parts) != 3 or not all(parts) or parts[1] != kind:
        raise ValueError(name)
    try:
        return get_interface('/'.join(parts))
    except (ImportError, AttributeError, ValueError):
        raise ValueError(name) from None


def type_name(msg_class: Any) -> str:
    """'pkg/msg/Name' of a generated class (services: 'pkg/srv/Name_Request')."""
    module = msg_class.__module__.split('.')
    return f'{module[0]}/{module[1]}/{msg_class.__name__}'
