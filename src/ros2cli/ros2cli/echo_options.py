"""The output options `ros2 topic echo` and `ros2 service echo` share, as ros2cli's."""

from __future__ import annotations

import argparse
from typing import Any

DEFAULT_TRUNCATE_LENGTH = 128


def unsigned_int(text: str) -> int:
    """argparse type for counts: ros2cli's message for anything but an integer >= 0."""
    try:
        value = int(text)
    except ValueError:
        value = -1
    if value < 0:
        raise argparse.ArgumentTypeError('value must be non-negative integer')
    return value


def add_output_options(parser: argparse.ArgumentParser) -> None:
    """--full-length, --truncate-length, --no-arr, --no-str, --flow-style."""
    parser.add_argument('--full-length', '-f', action='store_true',
                        help='Output all elements for arrays, bytes, and string with a length > '
                        "'--truncate-length', by default they are truncated after "
                        "'--truncate-length' elements with '...''")
    parser.add_argument('--truncate-length', '-l', type=unsigned_int,
                        default=DEFAULT_TRUNCATE_LENGTH,
                        help='The length to truncate arrays, bytes, and string to '
                        f'(default: {DEFAULT_TRUNCATE_LENGTH})')
    parser.add_argument('--no-arr', action='store_true',
                        help="Don't print array fields of messages")
    parser.add_argument('--no-str', action='store_true',
                        help="Don't print string fields of messages")
    parser.add_argument('--flow-style', action='store_true',
                        help='Print collections in the block style (not available with csv format)')


def conversion_options(args: argparse.Namespace) -> dict[str, Any]:
    """The keyword arguments of rosidl_runtime_py's conversions that those options select."""
    return {'truncate_length': None if args.full_length else args.truncate_length,
            'no_arr': args.no_arr, 'no_str': args.no_str}
