"""ros2 service find: Output a list of available services of a given type."""

from __future__ import annotations

import argparse

from ros2cli.names import print_names
from ros2cli.verb_context import VerbContext

from ros2service.api import includes_hidden, query_graph

HELP = 'Output a list of available services of a given type'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('service_type', help="Name of the ROS service type to filter for "
                        "(e.g. 'rcl_interfaces/srv/ListParameters')")
    parser.add_argument('-c', '--count-services', action='store_true',
                        help='Only display the number of services discovered')


def main(args: argparse.Namespace, context: VerbContext) -> int:
    print_names(
        [
            name
            for name, types in query_graph(args, context=context).services(includes_hidden(args))
            if args.service_type in types
        ],
        args.count_services,
        context=context,
    )
    return 0
