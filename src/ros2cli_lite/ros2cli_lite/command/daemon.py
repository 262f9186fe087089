"""ros2 daemon: start, stop, status (of the daemon for this shell's ROS settings)."""

from __future__ import annotations

import argparse


def add_arguments(parser: argparse.ArgumentParser) -> None:
    verbs = parser.add_subparsers(title='Commands', metavar='Call')
    p = verbs.add_parser('start', help="Start the daemon if it isn't running",
                         description="Start the daemon if it isn't running")
    p.add_argument('--debug', '-d', action='store_true', help='Print debug messages')
    p.set_defaults(_main=start_verb)
    p = verbs.add_parser('stop', help='Stop the daemon if it is running',
                         description='Stop the daemon if it is running')
    p.set_defaults(_main=stop_verb)
    p = verbs.add_parser('status', help='Output the status of the daemon',
                         description='Output the status of the daemon')
    p.set_defaults(_main=status_verb)


def start_verb(args: argparse.Namespace) -> int:
    from ros2cli_lite.daemon import client, protocol
    started = client.start()
    if args.debug:
        print(f'socket: {protocol.socket_path()}')
    print('The daemon has been started' if started else 'The daemon is already running')
    return 0


def stop_verb(args: argparse.Namespace) -> int:
    from ros2cli_lite.daemon import client
    print('The daemon has been stopped' if client.stop() else 'The daemon is not running')
    return 0


def status_verb(args: argparse.Namespace) -> int:
    from ros2cli_lite.daemon import client
    print('The daemon is running' if client.is_running() else 'The daemon is not running')
    return 0
