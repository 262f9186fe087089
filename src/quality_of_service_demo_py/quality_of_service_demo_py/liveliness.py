"""`ros2 run quality_of_service_demo_py liveliness 1000`: a talker and a listener with a
Liveliness lease; after --kill-publisher-after ms the talker goes away (AUTOMATIC: the
node is destroyed; MANUAL_BY_TOPIC: it stops asserting) and both report the change."""

from __future__ import annotations

import argparse
import sys

from rclpy.duration import Duration
from rclpy.event_handler import PublisherEventCallbacks, SubscriptionEventCallbacks
from rclpy.logging import get_logger
from rclpy.qos import LivelinessPolicy, QoSProfile

from quality_of_service_demo_py.common_nodes import Listener, Talker, positive_int, run

TOPIC = 'qos_liveliness_chatter'
POLICY_MAP = {'AUTOMATIC': LivelinessPolicy.AUTOMATIC,
              'MANUAL_BY_TOPIC': LivelinessPolicy.MANUAL_BY_TOPIC}


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser()
    parser.add_argument('liveliness_lease_duration', type=positive_int, help='Duration in '
                        'positive integer milliseconds of the Liveliness lease_duration QoS '
                        'setting.')
    parser.add_argument('--policy', type=str, choices=POLICY_MAP.keys(), default='AUTOMATIC',
                        help='The Liveliness policy type.')
    parser.add_argument('--topic-assert-period', type=int, default=0, help='How often (in '
                        'positive integer milliseconds) the Talker will manually assert the '
                        'liveliness of its Publisher.')
    parser.add_argument('--kill-publisher-after', type=int, default=3000, help='Shuts down '
                        'the Talker after this duration, in positive integer milliseconds.')
    return parser.parse_args(argv)


def log_liveliness(side: str):
    def callback(event) -> None:
        log = get_logger(side)
        log.info('Liveliness changed event:')
        for field in ('alive_count', 'not_alive_count', 'alive_count_change',
                      'not_alive_count_change'):
            log.info(f'  {field}: {getattr(event, field)}')
    return callback


def main() -> int:
    args = parse_args()
    policy = POLICY_MAP[args.policy]
    qos = QoSProfile(depth=10, liveliness=policy, liveliness_lease_duration=Duration(
        seconds=args.liveliness_lease_duration / 1000.0))

    def nodes(executor):
        listener = Listener(TOPIC, qos, SubscriptionEventCallbacks(
            liveliness=log_liveliness('listener')))
        talker = Talker(TOPIC, qos, PublisherEventCallbacks(liveliness=log_liveliness('talker')),
                        assert_topic_period=args.topic_assert_period / 1000.0)

        def kill_talker() -> None:
            if policy == LivelinessPolicy.AUTOMATIC:
                executor.remove_node(talker)
                talker.destroy_node()
            else:
                talker.stop()
            kill_timer.cancel()
        if args.kill_publisher_after > 0:
            kill_timer = listener.create_timer(args.kill_publisher_after / 1000.0, kill_talker)
        return [listener, talker]
    return run(nodes)


if __name__ == '__main__':
    sys.exit(main())
