"""ros2 topic delay: Display delay of topic from timestamp in header."""

from __future__ import annotations

import argparse
import math

from ros2cli.verb_context import VerbContext

from ros2topic.api import positive_int, report_every_second, wait_for_type
from ros2topic.verb import VerbExtension

HELP = 'Display delay of topic from timestamp in header'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('topic_name', help='Topic name to calculate the delay for')
    parser.add_argument('--window', '-w', type=positive_int, default=10000,
                        help='window size, in # of messages, for calculating rate (default: 10000)')


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from collections import deque

    from rclpy.qos import qos_profile_sensor_data
    from rclpy.time import Time
    from ros2cli.interface_types import type_name
    from ros2cli.node.direct import cli_node

    from ros2topic.api import apply_sim_time
    with cli_node(context, spin_time=args.spin_time) as node:
        apply_sim_time(node, args)
        msg_type = wait_for_type(node, args.topic_name, args.spin_time, context=context)
        if 'header' not in msg_type.get_fields_and_field_types():
            return (f'{type_name(msg_type)} has no header: the delay is measured from '
                    'header.stamp (use a stamped type, e.g. geometry_msgs/msg/TwistStamped)')
        clock = node.get_clock()
        delays: deque[int] = deque(maxlen=args.window)
        received = {'count': 0, 'printed': 0}

        def on_message(msg) -> None:
            now = clock.now()
            if now.nanoseconds == 0:  # simulated time not started yet
                return
            delays.append((now - Time.from_msg(msg.header.stamp)).nanoseconds)
            received['count'] += 1

        node.create_subscription(msg_type, args.topic_name, on_message,
                                 qos_profile_sensor_data)

        def report() -> None:
            if not delays:
                return
            if received['count'] == received['printed']:
                print('no new messages', flush=True, file=context.stdout)
                return
            received['printed'] = received['count']
            n = len(delays)
            mean = sum(delays) / n
            std = math.sqrt(sum((d - mean) ** 2 for d in delays) / n)
            print(f'average delay: {mean * 1e-9:.3f}\n\tmin: {min(delays) * 1e-9:.3f}s '
                  f'max: {max(delays) * 1e-9:.3f}s std dev: {std * 1e-9:.5f}s window: {n}',
                  flush=True, file=context.stdout)

        report_every_second(node, report, context=context)


class DelayVerb(VerbExtension):
    """Upstream's class of this verb, for code that drives it from Python."""
