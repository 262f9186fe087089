"""ros2 lifecycle nodes: Output a list of nodes with lifecycle."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2lifecycle.api import managed_node_names

HELP = 'Output a list of nodes with lifecycle'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('-a', '--all', action='store_true',
                        help='Display all nodes even hidden ones')
    parser.add_argument('-c', '--count-nodes', action='store_true',
                        help='Only display the number of nodes discovered')


def main(args: argparse.Namespace, context: VerbContext) -> int:
    names = managed_node_names(args, args.all, context=context)
    if args.count_nodes:
        print(len(names), file=context.stdout)
    for name in names if not args.count_nodes else ():
        print(name, file=context.stdout)
    return 0
