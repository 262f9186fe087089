"""ros2 interface package: Output a list of available interface types within one package."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2interface.api import interfaces_of

HELP = 'Output a list of available interface types within one package'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('-m', '--only-msgs', action='store_true',
                        help='Print out only the message types')
    parser.add_argument('-s', '--only-srvs', action='store_true',
                        help='Print out only the service types')
    parser.add_argument('-a', '--only-actions', action='store_true',
                        help='Print out only the action types')
    parser.add_argument('package_name', help="Name of the ROS package (e.g. 'example_interfaces')")


def main(args: argparse.Namespace, context: VerbContext) -> int:
    names = interfaces_of(args.package_name)
    chosen = [kind for kind, flag in (('msg', args.only_msgs), ('srv', args.only_srvs),
                                      ('action', args.only_actions)) if flag]
    if chosen:
        # Upstream lists the chosen kinds one after the other: messages, services, actions.
        names = [n for kind in chosen for n in names if n.split('/', 1)[0] == kind]
    for name in names:
        print(f'{args.package_name}/{name}', file=context.stdout)
    return 0
