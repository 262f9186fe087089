"""ros2 lifecycle: nodes, list, get, set.

One module per verb, as ros2lifecycle's verb/ package: each adds its own arguments and
holds its main(); what the verbs share is in ros2lifecycle.api.
"""

from __future__ import annotations

import argparse
import importlib

from ros2cli.command import add_graph_verb

VERBS = ('get', 'list', 'nodes', 'set')


def add_arguments(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(title='Commands', metavar='Call')
    for name in VERBS:
        module = importlib.import_module(f'ros2lifecycle.verb.{name}')
        module.add_arguments(add_graph_verb(verbs, name, module.main, module.HELP))
