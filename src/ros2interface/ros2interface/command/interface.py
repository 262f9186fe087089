"""ros2 interface: list, packages, package, show, proto (definition files of the ament index).

One module per verb, as upstream's verb/ packages: each adds its own arguments and
holds its main(); what several verbs share is in ros2interface.api.
"""

from __future__ import annotations

import argparse
import importlib

VERBS = ('list', 'packages', 'package', 'show', 'proto')


def add_arguments(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(title='Commands', metavar='Call')

    def verb(name: str, func, help_text: str) -> argparse.ArgumentParser:
        parser = verbs.add_parser(name, help=help_text)
        parser.set_defaults(_main=func)
        return parser

    for name in VERBS:
        module = importlib.import_module(f'ros2interface.verb.{name}')
        module.add_arguments(verb(name, module.main, module.HELP))
