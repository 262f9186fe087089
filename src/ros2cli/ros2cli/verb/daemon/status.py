"""ros2 daemon status: Output the status of the daemon."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

HELP = 'Output the status of the daemon'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    del parser  # no arguments of its own


def main(args: argparse.Namespace, context: VerbContext) -> int:
    from ros2cli.daemon import client
    print(
        'The daemon is running' if client.is_running() else 'The daemon is not running',
        file=context.stdout,
    )
    return 0
