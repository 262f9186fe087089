"""ros2 action list: Output a list of action names."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2action.api import query_graph

HELP = 'Output a list of action names'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('-t', '--show-types', action='store_true',
                        help='Additionally show the action type')
    parser.add_argument('-c', '--count-actions', action='store_true',
                        help='Only display the number of actions discovered')


def main(args: argparse.Namespace, context: VerbContext) -> int:
    found = query_graph(args, context=context).actions()
    if args.count_actions:
        print(len(found), file=context.stdout)
        return 0
    for name, types in found:
        print(f'{name} [{", ".join(types)}]' if args.show_types else name, file=context.stdout)
    return 0
