"""ros2 daemon stop: Stop the daemon if it is running."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

HELP = 'Stop the daemon if it is running'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    del parser  # no arguments of its own


def main(args: argparse.Namespace, context: VerbContext) -> int:
    from ros2cli.daemon import client
    print(
        'The daemon has been stopped' if client.stop() else 'The daemon is not running',
        file=context.stdout,
    )
    return 0
