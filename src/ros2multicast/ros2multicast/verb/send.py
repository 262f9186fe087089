"""ros2 multicast send: Send a single UDP multicast packet (out of the loopback interface)."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2multicast.api import MAX_TTL, MESSAGE, send
from ros2multicast.verb import add_group_argument, add_port_argument

HELP = 'Send a single UDP multicast packet'


def ttl_value(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = -1
    if not 0 <= value <= MAX_TTL:
        raise argparse.ArgumentTypeError(
            f'value must be 0 or {MAX_TTL} (the datagram stays on this machine)')
    return value


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_group_argument(parser)
    add_port_argument(parser)
    parser.add_argument('--ttl', type=ttl_value,
                        help='The multicast TTL (0 or 1; default 0: loopback only)')


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    print('Sending one UDP multicast datagram...', file=context.stdout)
    try:
        send(MESSAGE, group=args.group, port=args.port, ttl=args.ttl)
    except OSError as error:
        return f'Could not send to {args.group}:{args.port}: {error.strerror or error}'
    return 0
