"""ros2 daemon stop: Stop the daemon if it is running."""

from __future__ import annotations

import argparse

HELP = 'Stop the daemon if it is running'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    del parser  # no arguments of its own


def main(args: argparse.Namespace) -> int:
    from ros2cli.daemon import client
    print('The daemon has been stopped' if client.stop() else 'The daemon is not running')
    return 0
