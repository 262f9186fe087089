"""ros2 pkg executables: Output a list of package specific executables."""

from __future__ import annotations

import argparse
import os

from ros2cli.verb_context import VerbContext

from ros2pkg.api import executables, get_package_names

HELP = 'Output a list of package specific executables'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('package_name', nargs='?', help='The package name')
    parser.add_argument('--full-path', action='store_true',
                        help='Show full path of each executable')


def main(args: argparse.Namespace, context: VerbContext) -> int:
    names = sorted(get_package_names()) if args.package_name is None else [args.package_name]
    for name in names:
        _, paths = executables(name)
        for path in paths:
            print(
                path if args.full_path else f'{name} {os.path.basename(path)}', file=context.stdout
            )
    return 0
