"""`ros2 run quality_of_service_demo_py lifespan 1000`: a transient-local talker publishes
--publish-count messages with a Lifespan; a listener that subscribes --subscribe-after ms
later gets only those still within their lifespan."""

from __future__ import annotations

import argparse
import sys

from rclpy.duration import Duration
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

from quality_of_service_demo_py.common_nodes import Listener, Talker, positive_int, run

TOPIC = 'qos_lifespan_chatter'


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser()
    parser.add_argument('lifespan', type=positive_int, help='Duration in positive integer '
                        'milliseconds of the Lifespan QoS setting.')
    parser.add_argument('--history', type=positive_int, default=10, help="The depth of the "
                        "Publisher's history queue - the maximum number of messages it will "
                        'store for late-joining subscriptions.')
    parser.add_argument('--publish-count', type=positive_int, default=10,
                        help='How many messages to publish before stopping.')
    parser.add_argument('--subscribe-after', type=positive_int, default=2500, help='The '
                        'Subscriber will be created this long (in positive integer '
                        'milliseconds) after application startup.')
    return parser.parse_args(argv)


def main() -> int:
    args = parse_args()
    # Reliable and transient local: the talker keeps its messages for a late subscriber,
    # and Lifespan decides which of them are still delivered.
    qos = QoSProfile(depth=args.history, reliability=ReliabilityPolicy.RELIABLE,
                     durability=DurabilityPolicy.TRANSIENT_LOCAL,
                     lifespan=Duration(seconds=args.lifespan / 1000.0))

    def nodes(_executor):
        listener = Listener(TOPIC, qos, None, defer_subscribe=True)
        talker = Talker(TOPIC, qos, None, publish_count=args.publish_count)
        listener.create_timer(args.subscribe_after / 1000.0, listener.start_listening)
        return [listener, talker]
    return run(nodes)


if __name__ == '__main__':
    sys.exit(main())
