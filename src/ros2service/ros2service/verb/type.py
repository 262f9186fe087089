"""ros2 service type: Output a service's type."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2service.api import lookup

HELP = "Output a service's type"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('service_name', help="Name of the ROS service to get type (e.g. '/talker')")


def main(args: argparse.Namespace, context: VerbContext) -> int:
    found, _ = lookup(args, context=context)
    if found is None:
        return 1
    for service_type in found:
        print(service_type, file=context.stdout)
    return 0
