"""ros2 service list: Output a list of available services."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2service.api import includes_hidden, query_graph

HELP = 'Output a list of available services'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('-t', '--show-types', action='store_true',
                        help='Additionally show the service type')
    parser.add_argument('-c', '--count-services', action='store_true',
                        help='Only display the number of services discovered')


def main(args: argparse.Namespace, context: VerbContext) -> int:
    found = query_graph(args, context=context).services(includes_hidden(args))
    if args.count_services:
        print(len(found), file=context.stdout)
        return 0
    for name, types in found:
        print(f'{name} [{", ".join(types)}]' if args.show_types else name, file=context.stdout)
    return 0
