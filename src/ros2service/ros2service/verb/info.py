"""ros2 service info: Print information about a service."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2service.api import lookup

HELP = 'Print information about a service'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('service_name', help="Name of the ROS service to get info (e.g. "
                        "'/add_two_ints')")


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    found, graph = lookup(args, context=context)
    if found is None:
        return f"Unknown service '{args.service_name}'"
    servers, clients = graph.service_counts(args.service_name)
    print(f'Type: {found[0] if len(found) == 1 else found}', file=context.stdout)
    print(f'Clients count: {clients}', file=context.stdout)
    print(f'Services count: {servers}', file=context.stdout)
    return 0
