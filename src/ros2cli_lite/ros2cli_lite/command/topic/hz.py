"""ros2 topic hz: Print the average publishing rate to screen."""

from __future__ import annotations

import argparse
import itertools
import math
import time

from ros2cli_lite.command.topic.api import positive_int, wait_for_type

HELP = 'Print the average publishing rate to screen'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('topic_name', help="Name of the ROS topic to listen to (e.g. '/chatter')")
    parser.add_argument('--window', '-w', type=positive_int, default=10000,
                        help='window size, in # of messages, for calculating rate (default: 10000)')


def main(args: argparse.Namespace) -> int | str:
    from rclpy.qos import qos_profile_sensor_data

    from ros2cli_lite.node import cli_node, spin_once
    with cli_node(spin_time=args.spin_time) as node:
        msg_type = wait_for_type(node, args.topic_name, args.spin_time)
        stamps: list[float] = []

        def callback(_msg) -> None:
            stamps.append(time.monotonic())
            if len(stamps) > args.window + 1:
                del stamps[0]

        node.create_subscription(msg_type, args.topic_name, callback, qos_profile_sensor_data)
        last_print = time.monotonic()
        printed_count = 0
        while True:
            spin_once(node, 0.05)
            now = time.monotonic()
            if now - last_print < 1.0:
                continue
            last_print = now
            if len(stamps) < 2 or len(stamps) == printed_count:
                continue
            printed_count = len(stamps)
            deltas = [b - a for a, b in itertools.pairwise(stamps)]
            n = len(deltas)
            mean = sum(deltas) / n
            std = math.sqrt(sum((d - mean) ** 2 for d in deltas) / n)
            print(f'average rate: {1.0 / mean:.3f}\n\tmin: {min(deltas):.3f}s max: '
                  f'{max(deltas):.3f}s std dev: {std:.5f}s window: {n + 1}', flush=True)
