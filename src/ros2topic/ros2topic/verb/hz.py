"""ros2 topic hz: Print the average publishing rate to screen."""

from __future__ import annotations

import argparse
import itertools
import math
import time

from ros2cli.verb_context import VerbContext

from ros2topic.api import message_filter, positive_int, wait_for_type
from ros2topic.verb import VerbExtension

HELP = 'Print the average publishing rate to screen'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('topic_name', help="Name of the ROS topic to listen to (e.g. '/chatter')")
    parser.add_argument('--window', '-w', type=positive_int, default=10000, metavar='WINDOW',
                        help='window size, in # of messages, for calculating rate (default: 10000)')
    parser.add_argument('--filter', dest='filter_expr', default=None, metavar='EXPR',
                        help='only measure messages matching the specified Python expression')
    parser.add_argument('--wall-time', dest='use_wtime', action='store_true',
                        help='calculates rate using wall time which can be helpful when clock '
                        'is not published during simulation')


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from rclpy.qos import qos_profile_sensor_data
    from ros2cli.node.direct import cli_node, spin_once

    from ros2topic.api import apply_sim_time
    keep = message_filter(args.filter_expr)
    with cli_node(context, spin_time=args.spin_time) as node:
        apply_sim_time(node, args)
        msg_type = wait_for_type(node, args.topic_name, args.spin_time, context=context)
        clock = node.get_clock()
        # Arrival times in ns: the node's clock (sim time with -s), or the wall clock.
        stamps: list[int] = []
        received = [0]  # messages measured so far: a report only when new ones came

        def callback(msg) -> None:
            if keep is not None and not keep(msg):
                return
            now = time.time_ns() if args.use_wtime else clock.now().nanoseconds
            if stamps and now < stamps[-1]:
                print('time has reset, resetting counters', flush=True, file=context.stdout)
                stamps.clear()
            stamps.append(now)
            received[0] += 1
            if len(stamps) > args.window + 1:
                del stamps[0]

        node.create_subscription(msg_type, args.topic_name, callback, qos_profile_sensor_data)
        last_print = time.monotonic()
        printed_count = 0
        while True:
            spin_once(node, 0.05, context)
            now = time.monotonic()
            if now - last_print < 1.0:
                continue
            last_print = now
            if len(stamps) < 2 or received[0] == printed_count:
                continue
            printed_count = received[0]
            deltas = [(b - a) * 1e-9 for a, b in itertools.pairwise(stamps)]
            n = len(deltas)
            mean = sum(deltas) / n
            if mean <= 0:
                continue
            std = math.sqrt(sum((d - mean) ** 2 for d in deltas) / n)
            print(
                f'average rate: {1.0 / mean:.3f}\n\tmin: {min(deltas):.3f}s max: '
                f'{max(deltas):.3f}s std dev: {std:.5f}s window: {n + 1}',
                flush=True,
                file=context.stdout,
            )


class HzVerb(VerbExtension):
    """Upstream's class of this verb, for code that drives it from Python."""
