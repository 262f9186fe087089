"""ros2 param: list, get, set, describe, dump, load, delete (through the node's rcl_interfaces
services).

One module per verb, as upstream's verb/ packages: each adds its own arguments and
holds its main(); what several verbs share is in ros2param.api.
"""

from __future__ import annotations

import argparse
import importlib

from ros2cli.command import add_graph_verb

VERBS = ('list', 'get', 'set', 'describe', 'dump', 'load', 'delete')


def add_arguments(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(title='Commands', metavar='Call')

    def verb(name: str, func, help_text: str) -> argparse.ArgumentParser:
        parser = add_graph_verb(verbs, name, func, help_text)
        parser.add_argument('--include-hidden-nodes', action='store_true',
                            help='Consider hidden nodes as well')
        return parser

    for name in VERBS:
        module = importlib.import_module(f'ros2param.verb.{name}')
        module.add_arguments(verb(name, module.main, module.HELP))
