"""ros2 interface list: List all interface types available."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2interface.api import interface_packages, interfaces_of

HELP = 'List all interface types available'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('-m', '--only-msgs', action='store_true',
                        help='Print out only the message types')
    parser.add_argument('-s', '--only-srvs', action='store_true',
                        help='Print out only the service types')
    parser.add_argument('-a', '--only-actions', action='store_true',
                        help='Print out only the action types')


def _names_by_kind(kind: str) -> dict[str, list[str]]:
    result = {}
    for package in interface_packages():
        names = sorted(n.split('/', 1)[1] for n in interfaces_of(package)
                       if n.startswith(kind + '/'))
        if names:
            result[package] = names
    return result


def main(args: argparse.Namespace, context: VerbContext) -> int:
    sections = [('Messages:', 'msg', args.only_msgs), ('Services:', 'srv', args.only_srvs),
                ('Actions:', 'action', args.only_actions)]
    only = args.only_msgs or args.only_srvs or args.only_actions
    for title, kind, chosen in sections:
        if only and not chosen:
            continue
        print(title, file=context.stdout)
        by_package = _names_by_kind(kind)
        for package in sorted(by_package):
            for name in by_package[package]:
                print(f'    {package}/{kind}/{name}', file=context.stdout)
    return 0
