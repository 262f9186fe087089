"""ros2 interface packages: Output a list of packages that provide interfaces."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2interface.api import interface_packages, interfaces_of

HELP = 'Output a list of packages that provide interfaces'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('-m', '--only-msgs', action='store_true')
    parser.add_argument('-s', '--only-srvs', action='store_true')
    parser.add_argument('-a', '--only-actions', action='store_true')


def main(args: argparse.Namespace, context: VerbContext) -> int:
    kinds = [k for k, chosen in (('msg', args.only_msgs), ('srv', args.only_srvs),
                                 ('action', args.only_actions)) if chosen]
    for package in sorted(interface_packages()):
        if kinds and not any(n.split('/')[0] in kinds for n in interfaces_of(package)):
            continue
        print(package, file=context.stdout)
    return 0
