"""ros2 daemon status: Output the status of the daemon."""

from __future__ import annotations

import argparse

HELP = 'Output the status of the daemon'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    del parser  # no arguments of its own


def main(args: argparse.Namespace) -> int:
    from ros2cli.daemon import client
    print('The daemon is running' if client.is_running() else 'The daemon is not running')
    return 0
