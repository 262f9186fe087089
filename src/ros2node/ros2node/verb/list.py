"""ros2 node list: Output a list of available nodes."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

HELP = 'Output a list of available nodes'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('-a', '--all', action='store_true',
                        help='Display all nodes even hidden ones')
    parser.add_argument('-c', '--count-nodes', action='store_true',
                        help='Only display the number of nodes discovered')


DUPLICATE_WARNING = ('WARNING: Be aware that there are nodes in the graph that share an exact '
                     'name, which can have unintended side effects.')


def main(args: argparse.Namespace, context: VerbContext) -> int:
    from ros2cli.graph import graph_source
    with graph_source(not args.no_daemon, args.spin_time, context) as source:
        full = source.graph().node_names(args.all)
    if args.count_nodes:
        print(len(full), file=context.stdout)
        return 0
    if len(set(full)) != len(full):
        print(DUPLICATE_WARNING, file=context.stderr)
    for name in full:
        print(name, file=context.stdout)
    return 0
