"""ros2 topic bw: Display bandwidth used by topic."""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext

from ros2topic.api import positive_int, report_every_second, wait_for_type
from ros2topic.verb import VerbExtension

HELP = 'Display bandwidth used by topic'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('topic_name', help='Topic name to monitor for bandwidth utilization')
    parser.add_argument('--window', '-w', type=positive_int, default=100, metavar='WINDOW',
                        help='maximum window size, in # of messages, for calculating rate '
                        '(default: 100)')


def _size_text(count: float, scale: float) -> str:
    if scale == 1:
        return f'{count:.0f} B'
    return f'{count / scale:.2f} {"KB" if scale == 1e3 else "MB"}'


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from collections import deque

    from rclpy.qos import qos_profile_sensor_data
    from ros2cli.node.direct import cli_node

    from ros2topic.api import apply_sim_time
    with cli_node(context, spin_time=args.spin_time) as node:
        apply_sim_time(node, args)
        msg_type = wait_for_type(node, args.topic_name, args.spin_time, context=context)
        clock = node.get_clock()
        window: deque[tuple[int, int]] = deque(maxlen=args.window)  # (ns received, bytes)

        def on_message(data: bytes) -> None:
            window.append((clock.now().nanoseconds, len(data)))

        node.create_subscription(msg_type, args.topic_name, on_message,
                                 qos_profile_sensor_data, raw=True)
        print(f'Subscribed to [{args.topic_name}]', flush=True, file=context.stdout)

        def report() -> None:
            if len(window) < 2:
                return
            elapsed = (clock.now().nanoseconds - window[0][0]) * 1e-9
            if elapsed <= 0:
                print('WARNING: time is reset!', file=context.stderr)
                window.clear()
                return
            sizes = [size for _, size in window]
            rate = sum(sizes) / elapsed
            scale = 1 if rate < 1e3 else 1e3 if rate < 1e6 else 1e6
            mean, low, high = (_size_text(v, scale) for v in
                               (sum(sizes) / len(sizes), min(sizes), max(sizes)))
            print(
                f'{_size_text(rate, scale)}/s from {len(sizes)} messages\n'
                f'\tMessage size mean: {mean} min: {low} max: {high}',
                flush=True,
                file=context.stdout,
            )

        report_every_second(node, report, context=context)


class BwVerb(VerbExtension):
    """Upstream's class of this verb, for code that drives it from Python."""
