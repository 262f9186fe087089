"""ros2 pkg: create, executables, list, prefix, xml (one module per verb under ros2pkg.verb)."""

from __future__ import annotations

import argparse
import importlib

VERBS = ('create', 'executables', 'list', 'prefix', 'xml')


def add_arguments(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(title='Commands', metavar='Call')
    for name in VERBS:
        module = importlib.import_module(f'ros2pkg.verb.{name}')
        verb = verbs.add_parser(name, help=module.HELP, description=module.HELP)
        verb.set_defaults(_main=module.main)
        module.add_arguments(verb)
