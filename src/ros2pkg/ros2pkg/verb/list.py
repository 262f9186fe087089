"""ros2 pkg list: Output a list of available packages."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2pkg.api import get_package_names

HELP = 'Output a list of available packages'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    pass


def main(args: argparse.Namespace, context: VerbContext) -> int:
    for name in sorted(get_package_names()):
        print(name, file=context.stdout)
    return 0
