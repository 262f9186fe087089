"""ros2 param list: Output a list of available parameters."""

from __future__ import annotations

import argparse
import re

from ros2cli.verb_context import VerbContext

from ros2param.api import TYPE_NAMES, call, find_node

HELP = 'Output a list of available parameters'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('node_name', nargs='?', help='Name of the ROS node')
    parser.add_argument('--param-prefixes', nargs='+', default=[],
                        help='Only list parameters with the provided prefixes')
    parser.add_argument('--param-type', action='store_true',
                        help='Print parameter types with parameter names')
    parser.add_argument('--filter', nargs=1, type=_regex,
                        help='Only parameters matching the regex expression will be showed. '
                        'Supports `re` regex syntax.')


def _regex(text: str) -> re.Pattern:
    """argparse type of --filter: a usage error naming what is wrong with the pattern."""
    try:
        return re.compile(text)
    except re.error as error:
        raise argparse.ArgumentTypeError(
            f"'{text}' is not a regular expression: {error}") from None


def runs_in_daemon(_args: argparse.Namespace) -> bool:
    """One exchange with the node: the daemon may run it for the CLI (ros2cli.daemon.verb_host)."""
    return True


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from ros2cli.graph import graph_source
    if args.node_name:
        target = find_node(args, context=context)
        if target is None:
            return 'Node not found'
        targets = [target]
        # The node may be listed before its parameter services have been discovered.
        with graph_source(not args.no_daemon, args.spin_time, context) as source:
            source.graph(ready=lambda g: f'{target}/list_parameters' in dict(g.services(True)))
    else:
        with graph_source(not args.no_daemon, args.spin_time, context) as source:
            graph = source.graph()
        services = dict(graph.services(True))
        targets = [name for name in graph.node_names(args.include_hidden_nodes)
                   if f'{name}/list_parameters' in services]
    if targets:
        _list_parameters(args, sorted(set(targets)), context)
    return 0


def _list_parameters(args: argparse.Namespace, targets: list[str], context: VerbContext) -> None:
    """Ask each node for its parameters directly (the daemon never calls a node)."""
    from rcl_interfaces.srv import DescribeParameters, ListParameters
    from ros2cli.node.direct import cli_node
    with cli_node(context, spin_time=args.spin_time) as node:
        for target in targets:
            request = ListParameters.Request()
            request.prefixes = list(args.param_prefixes)
            response = call(
                node, ListParameters, f'{target}/list_parameters', request, context=context
            )
            names = sorted(response.result.names)
            if args.filter is not None:  # matched at the start of the name, as upstream
                names = [name for name in names if args.filter[0].match(name)]
            if not args.node_name and names:
                print(f'{target}:', file=context.stdout)
            types = {}
            if args.param_type:
                described = call(
                    node,
                    DescribeParameters,
                    f'{target}/describe_parameters',
                    DescribeParameters.Request(names=names),
                    context=context,
                )
                types = {
                    d.name: TYPE_NAMES.get(d.type, 'unknown type') for d in described.descriptors
                }
            for name in names:
                print(
                    f'  {name} (type: {types[name]})' if args.param_type else f'  {name}',
                    file=context.stdout,
                )
