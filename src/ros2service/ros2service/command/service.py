"""ros2 service: list, type, find, info, call, echo.

One module per verb, as upstream's verb/ packages: each adds its own arguments and
holds its main(); what several verbs share is in ros2service.api.
"""

from __future__ import annotations

import argparse
import importlib

from ros2cli.command import add_graph_verb

from ros2service.api import HIDDEN

VERBS = ('list', 'type', 'find', 'info', 'call', 'echo')


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(HIDDEN, action='store_true', help='Consider hidden services as well')
    verbs = parser.add_subparsers(title='Commands', metavar='Call')

    def verb(name: str, func, help_text: str) -> argparse.ArgumentParser:
        return add_graph_verb(verbs, name, func, help_text, HIDDEN,
                              'include_hidden_services_verb')

    for name in VERBS:
        module = importlib.import_module(f'ros2service.verb.{name}')
        module.add_arguments(verb(name, module.main, module.HELP))
