"""What both verbs share: the group and port options, checked where they enter."""

from __future__ import annotations

import argparse
import ipaddress

from ros2multicast.api import DEFAULT_GROUP, DEFAULT_PORT


def multicast_group(text: str) -> str:
    """Only a multicast group: any other address would send a unicast datagram off loopback."""
    try:
        address = ipaddress.IPv4Address(text)
    except ValueError:
        address = None
    if address is None or not address.is_multicast:
        raise argparse.ArgumentTypeError(
            f"'{text}' is not an IPv4 multicast address (224.0.0.0 to 239.255.255.255)")
    return text


def port_number(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = -1
    if not 0 < value < 65536:
        raise argparse.ArgumentTypeError('value must be a positive integer up to 65535')
    return value


def add_group_argument(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('--group', type=multicast_group, default=DEFAULT_GROUP,
                        help='The multicast group address')


def add_port_argument(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('--port', type=port_number, default=DEFAULT_PORT,
                        help='The multicast port')
