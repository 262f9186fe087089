"""ros2 node: list, info."""

from __future__ import annotations

import argparse
import sys

from ros2cli_lite.api import add_graph_verb, full_node_name, is_hidden, is_hidden_node

DUPLICATE_WARNING = ('WARNING: Be aware that there are nodes in the graph that share an exact '
                     'name, which can have unintended side effects.')


def add_arguments(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(title='Commands', metavar='Call')

    def verb(name: str, func, help_text: str) -> argparse.ArgumentParser:
        return add_graph_verb(verbs, name, func, help_text)

    p = verb('list', list_verb, 'Output a list of available nodes')
    p.add_argument('-a', '--all', action='store_true',
                   help='Display all nodes even hidden ones')
    p.add_argument('-c', '--count-nodes', action='store_true',
                   help='Only display the number of nodes discovered')
    p = verb('info', info_verb, 'Output information about a node')
    p.add_argument('node_name', help='Fully qualified node name to request information with '
                   'Pub/Sub/Service/Action')
    p.add_argument('--include-hidden', action='store_true', help='Display hidden topics, '
                   'services, and actions as well')


def node_names(node, include_hidden: bool) -> list[tuple[str, str, str]]:
    """(full name, name, namespace) of every node, sorted by full name."""
    result = []
    for name, namespace in node.get_node_names_and_namespaces():
        if include_hidden or not is_hidden_node(name):
            result.append((full_node_name(name, namespace), name, namespace))
    return sorted(result)


def list_verb(args: argparse.Namespace) -> int:
    from ros2cli_lite.api import cli_node, wait_for_graph
    with cli_node() as node:
        wait_for_graph(node)
        names = node_names(node, args.all)
    if args.count_nodes:
        print(len(names))
        return 0
    full = [n[0] for n in names]
    if len(set(full)) != len(full):
        print(DUPLICATE_WARNING, file=sys.stderr)
    for name in full:
        print(name)
    return 0


def _section(title: str, entries: list[tuple[str, list[str]]], include_hidden: bool) -> None:
    print(f'  {title}:')
    lines = [f'    {name}: {", ".join(types)}' for name, types in entries
             if include_hidden or not is_hidden(name)]
    print('\n'.join(lines))


def info_verb(args: argparse.Namespace) -> int | str:
    from rclpy.action.graph import (
        get_action_client_names_and_types_by_node,
        get_action_server_names_and_types_by_node,
    )

    from ros2cli_lite.api import cli_node, wait_for_graph
    with cli_node() as node:
        def matches():
            return [n for n in node_names(node, True) if n[0] == args.node_name]
        wait_for_graph(node, ready=lambda: bool(matches()))
        found = matches()
        if not found:
            return f"Unable to find node '{args.node_name}'"
        if len(found) > 1:
            print(f'There are {len(found)} nodes in the graph with the exact name '
                  f'"{args.node_name}". You are seeing information about only one of them.',
                  file=sys.stderr)
        _, name, namespace = found[0]
        hidden = args.include_hidden
        print(args.node_name)
        _section('Subscribers', node.get_subscriber_names_and_types_by_node(name, namespace),
                 hidden)
        _section('Publishers', node.get_publisher_names_and_types_by_node(name, namespace),
                 hidden)
        _section('Service Servers', node.get_service_names_and_types_by_node(name, namespace),
                 hidden)
        _section('Service Clients', node.get_client_names_and_types_by_node(name, namespace),
                 hidden)
        _section('Action Servers',
                 get_action_server_names_and_types_by_node(node, name, namespace), hidden)
        _section('Action Clients',
                 get_action_client_names_and_types_by_node(node, name, namespace), hidden)
    return 0
