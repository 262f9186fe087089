"""ros2 multicast receive: Receive a single UDP multicast packet (joined on loopback)."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2multicast.api import receive
from ros2multicast.verb import add_group_argument, add_port_argument

HELP = 'Receive a single UDP multicast packet'


def positive_seconds(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        value = -1.0
    if not 0 < value < float('inf'):
        raise argparse.ArgumentTypeError('value must be a positive number of seconds')
    return value


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_group_argument(parser)
    add_port_argument(parser)
    parser.add_argument('--timeout', type=positive_seconds, default=None,
                        help='Give up after this many seconds (default: wait until Ctrl-C)')


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    print('Waiting for UDP multicast datagram...', flush=True, file=context.stdout)
    try:
        data, (host, port) = receive(group=args.group, port=args.port, timeout=args.timeout)
    except TimeoutError:
        return f'No UDP multicast datagram received within {args.timeout:g} s'
    except KeyboardInterrupt:
        return 0
    except OSError as error:
        return f'Could not receive on {args.group}:{args.port}: {error.strerror or error}'
    print(f"Received from {host}:{port}: '{data.decode('utf-8', 'replace')}'", file=context.stdout)
    return 0
