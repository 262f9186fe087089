"""`ros2 run quality_of_service_demo_py deadline 600`: a talker and a listener with a
Deadline QoS; the talker pauses after --publish-for ms for --pause-for ms, and both report
the deadlines missed meanwhile."""

from __future__ import annotations

import argparse
import sys

from rclpy.duration import Duration
from rclpy.event_handler import PublisherEventCallbacks, SubscriptionEventCallbacks
from rclpy.logging import get_logger
from rclpy.qos import QoSProfile

from quality_of_service_demo_py.common_nodes import Listener, Talker, positive_int, run

TOPIC = 'qos_deadline_chatter'


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser()
    parser.add_argument('deadline', type=positive_int, help='Duration in positive integer '
                        'milliseconds of the Deadline QoS setting.')
    parser.add_argument('--publish-for', type=positive_int, default=5000, help='Duration in '
                        'positive integer milliseconds to publish until pausing the talker.')
    parser.add_argument('--pause-for', type=positive_int, default=1000, help='Duration in '
                        'positive integer milliseconds to pause the talker before beginning '
                        'to publish again.')
    return parser.parse_args(argv)


def main() -> int:
    args = parse_args()
    qos = QoSProfile(depth=10, deadline=Duration(seconds=args.deadline / 1000.0))

    def missed(side: str, what: str):
        return lambda event: get_logger(side).info(
            f'{what} deadline missed - total {event.total_count} delta '
            f'{event.total_count_change}')

    def nodes(_executor):
        listener = Listener(TOPIC, qos, SubscriptionEventCallbacks(
            deadline=missed('listener', 'Requested')))
        talker = Talker(TOPIC, qos, PublisherEventCallbacks(
            deadline=missed('talker', 'Offered')))
        talker.create_timer(args.publish_for / 1000.0,
                            lambda: talker.pause_for(args.pause_for / 1000.0))
        return [listener, talker]
    return run(nodes)


if __name__ == '__main__':
    sys.exit(main())
