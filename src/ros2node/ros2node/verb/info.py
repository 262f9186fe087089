"""ros2 node info: Output information about a node."""

from __future__ import annotations

import argparse

from ros2cli.names import is_hidden
from ros2cli.verb_context import VerbContext

from ros2node.api import INFO_NONUNIQUE_WARNING_TEMPLATE

HELP = 'Output information about a node'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('node_name', help='Fully qualified node name to request information with '
                        'Pub/Sub/Service/Action')
    parser.add_argument('--include-hidden', action='store_true', help='Display hidden topics, '
                        'services, and actions as well')


def _section(
    title: str, entries: list[tuple[str, list[str]]], include_hidden: bool, context: VerbContext
) -> None:
    print(f'  {title}:', file=context.stdout)
    lines = [
        f'    {name}: {", ".join(types)}'
        for name, types in entries
        if include_hidden or not is_hidden(name)
    ]
    print('\n'.join(lines), file=context.stdout)


def _known(graph, name: str) -> bool:
    """The node is listed and its endpoints have arrived (they come after its name)."""
    info = graph.node(name)
    return info is not None and bool(info.publishers or info.service_servers)


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from ros2cli.graph import graph_source

    with graph_source(not args.no_daemon, args.spin_time, context) as source:
        graph = source.graph(detail=True, ready=lambda g: _known(g, args.node_name))
    # A hidden node is only found with --include-hidden, as upstream (exit 1 without it).
    count = graph.node_names(args.include_hidden).count(args.node_name)
    info = graph.node(args.node_name)
    if not count or info is None:
        return f"Unable to find node '{args.node_name}'"
    if count > 1:
        print(INFO_NONUNIQUE_WARNING_TEMPLATE.format(num_nodes=count, node_name=args.node_name),
              file=context.stderr)
    hidden = args.include_hidden
    print(args.node_name, file=context.stdout)
    _section('Subscribers', info.subscribers, hidden, context)
    _section('Publishers', info.publishers, hidden, context)
    _section('Service Servers', info.service_servers, hidden, context)
    _section('Service Clients', info.service_clients, hidden, context)
    _section('Action Servers', info.action_servers, hidden, context)
    _section('Action Clients', info.action_clients, hidden, context)
    return 0
