"""ros2 interface package: Output a list of available interface types within one package."""

from __future__ import annotations

import argparse

from ros2cli_lite.command.interface.api import interfaces_of

HELP = 'Output a list of available interface types within one package'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('package_name', help="Name of the ROS package (e.g. 'example_interfaces')")


def main(args: argparse.Namespace) -> int:
    for name in interfaces_of(args.package_name):
        print(f'{args.package_name}/{name}')
    return 0
