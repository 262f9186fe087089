"""ros2 daemon start: Start the daemon if it isn't running."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

HELP = "Start the daemon if it isn't running"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('--debug', '-d', action='store_true', help='Print debug messages')


def main(args: argparse.Namespace, context: VerbContext) -> int:
    from ros2cli.daemon import client, protocol
    started = client.start()
    if args.debug:
        print(f'socket: {protocol.socket_path()}', file=context.stdout)
    print(
        'The daemon has been started' if started else 'The daemon is already running',
        file=context.stdout,
    )
    return 0
