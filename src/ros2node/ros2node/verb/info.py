"""ros2 node info: Output information about a node."""

from __future__ import annotations

import argparse
import sys

from ros2cli.names import is_hidden

HELP = 'Output information about a node'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('node_name', help='Fully qualified node name to request information with '
                        'Pub/Sub/Service/Action')
    parser.add_argument('--include-hidden', action='store_true', help='Display hidden topics, '
                        'services, and actions as well')


def _section(title: str, entries: list[tuple[str, list[str]]], include_hidden: bool) -> None:
    print(f'  {title}:')
    lines = [f'    {name}: {", ".join(types)}' for name, types in entries
             if include_hidden or not is_hidden(name)]
    print('\n'.join(lines))


def _known(graph, name: str) -> bool:
    """The node is listed and its endpoints have arrived (they come after its name)."""
    info = graph.node(name)
    return info is not None and bool(info.publishers or info.service_servers)


def main(args: argparse.Namespace) -> int | str:
    from ros2cli.graph import graph_source
    with graph_source(not args.no_daemon, args.spin_time) as source:
        graph = source.graph(detail=True, ready=lambda g: _known(g, args.node_name))
    # A hidden node is only found with --include-hidden, as upstream (exit 1 without it).
    count = graph.node_names(args.include_hidden).count(args.node_name)
    info = graph.node(args.node_name)
    if not count or info is None:
        return f"Unable to find node '{args.node_name}'"
    if count > 1:
        print(f'There are {count} nodes in the graph with the exact name '
              f'"{args.node_name}". You are seeing information about only one of them.',
              file=sys.stderr)
    hidden = args.include_hidden
    print(args.node_name)
    _section('Subscribers', info.subscribers, hidden)
    _section('Publishers', info.publishers, hidden)
    _section('Service Servers', info.service_servers, hidden)
    _section('Service Clients', info.service_clients, hidden)
    _section('Action Servers', info.action_servers, hidden)
    _section('Action Clients', info.action_clients, hidden)
    return 0
