"""ros2 topic: list, type, find, info, echo, pub, hz, bw, delay.

One module per verb, as upstream's verb/ packages: each adds its own arguments and
holds its main(); what several verbs share is in ros2topic.api.
"""

from __future__ import annotations

import argparse
import importlib

from ros2cli.command import add_graph_verb

from ros2topic.api import HIDDEN

VERBS = ('list', 'type', 'find', 'info', 'echo', 'pub', 'hz', 'bw', 'delay')


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(HIDDEN, action='store_true', help='Consider hidden topics as well')
    verbs = parser.add_subparsers(title='Commands', metavar='Call')

    def verb(name: str, func, help_text: str) -> argparse.ArgumentParser:
        return add_graph_verb(verbs, name, func, help_text, HIDDEN, 'include_hidden_topics_verb')

    for name in VERBS:
        module = importlib.import_module(f'ros2topic.verb.{name}')
        module.add_arguments(verb(name, module.main, module.HELP))
