"""ros2 service info: Print information about a service."""

from __future__ import annotations

import argparse

from ros2service.api import lookup

HELP = 'Print information about a service'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('service_name', help="Name of the ROS service to get info (e.g. "
                        "'/add_two_ints')")


def main(args: argparse.Namespace) -> int | str:
    found, graph = lookup(args)
    if found is None:
        return f"Unknown service '{args.service_name}'"
    servers, clients = graph.service_counts(args.service_name)
    print(f'Type: {found[0] if len(found) == 1 else found}')
    print(f'Clients count: {clients}')
    print(f'Services count: {servers}')
    return 0
