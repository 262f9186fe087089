"""ros2 action: list, type, info, send_goal.

One module per verb, as upstream's verb/ packages: each adds its own arguments and
holds its main(); what several verbs share is in ros2action.api.
"""

from __future__ import annotations

import argparse
import importlib

from ros2cli.command import add_graph_verb

VERBS = ('list', 'type', 'info', 'send_goal')


def add_arguments(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(title='Commands', metavar='Call')

    def verb(name: str, func, help_text: str) -> argparse.ArgumentParser:
        return add_graph_verb(verbs, name, func, help_text)

    for name in VERBS:
        module = importlib.import_module(f'ros2action.verb.{name}')
        module.add_arguments(verb(name, module.main, module.HELP))
