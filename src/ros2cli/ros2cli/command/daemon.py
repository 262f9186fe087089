"""ros2 daemon: start, stop, status (of the daemon for this shell's ROS settings).

One module per verb, as ros2cli's verb/ packages: each adds its own arguments and
holds its main(); the daemon's code is ros2cli.daemon.
"""

from __future__ import annotations

import argparse
import importlib

VERBS = ('start', 'stop', 'status')


def add_arguments(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(title='Commands', metavar='Call')

    def verb(name: str, func, help_text: str) -> argparse.ArgumentParser:
        parser = verbs.add_parser(name, help=help_text, description=help_text)
        parser.set_defaults(_main=func)
        return parser

    for name in VERBS:
        module = importlib.import_module(f'ros2cli.verb.daemon.{name}')
        module.add_arguments(verb(name, module.main, module.HELP))
