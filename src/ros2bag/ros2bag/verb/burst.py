"""ros2 bag burst: publish a bag's messages as fast as possible (rosbag2_py.Player.burst)."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2bag.api import print_error
from ros2bag.verb.play import add_player_arguments, play_options


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_player_arguments(parser)
    parser.add_argument('-n', '--num-messages', type=int, default=0,
                        help='Number of messages to burst publish (0: all).')
    parser.set_defaults(_main=main)


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from rosbag2_py import Player

    options = play_options(args)
    if isinstance(options, str):
        return options
    from ros2bag.api import exit_now

    try:
        Player(args.log_level).burst(*options, args.num_messages)
        result: int | str = 0
    except RuntimeError as failure:
        result = print_error(str(failure))
    exit_now(result, context)  # the player's context is shut down: skip Fast DDS's static teardown
