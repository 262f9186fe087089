"""ros2 pkg prefix: Output the prefix path of a package."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import CliError, VerbContext

from ros2pkg.api import PACKAGE_NOT_FOUND, get_prefix_path, share_directory

HELP = 'Output the prefix path of a package'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('package_name', help='The package name')
    parser.add_argument('--share', action='store_true',
                        help='Show share directory for the package')


def main(args: argparse.Namespace, context: VerbContext) -> int:
    if args.share:
        print(share_directory(args.package_name), file=context.stdout)
        return 0
    prefix = get_prefix_path(args.package_name)
    if prefix is None:
        raise CliError(PACKAGE_NOT_FOUND)
    print(prefix, file=context.stdout)
    return 0
