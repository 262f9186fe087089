"""`ros2 run quality_of_service_demo_py incompatible_qos durability`: a talker and a
listener whose QoS differ in the named policy so that they cannot match; both report the
incompatibility. Ends after the talker's 5 messages."""

from __future__ import annotations

import argparse
import sys

from rclpy.duration import Duration
from rclpy.event_handler import (
    PublisherEventCallbacks,
    SubscriptionEventCallbacks,
    UnsupportedEventTypeError,
)
from rclpy.logging import get_logger
from rclpy.qos import DurabilityPolicy, LivelinessPolicy, QoSProfile, ReliabilityPolicy

from quality_of_service_demo_py.common_nodes import Listener, Talker, run

TOPIC = 'incompatible_qos_chatter'
NUM_MSGS = 5
# policy: (what it prints, the publisher's setting, the subscription's setting)
INCOMPATIBLE = {
    'durability': (
        'Durability incompatibility selected.\n'
        'Incompatibility condition: publisher durability kind < subscription durability kind.\n'
        'Setting publisher durability to: VOLATILE\n'
        'Setting subscription durability to: TRANSIENT_LOCAL\n',
        {'durability': DurabilityPolicy.VOLATILE},
        {'durability': DurabilityPolicy.TRANSIENT_LOCAL}),
    'deadline': (
        'Deadline incompatibility selected.\n'
        'Incompatibility condition: publisher deadline > subscription deadline.\n'
        'Setting publisher durability to: 2 seconds\n'
        'Setting subscription durability to: 1 second\n',
        {'deadline': Duration(seconds=2)}, {'deadline': Duration(seconds=1)}),
    'liveliness_policy': (
        'Liveliness Policy incompatibility selected.\n'
        'Incompatibility condition: publisher liveliness policy <subscripition liveliness '
        'policy.\n'
        'Setting publisher liveliness policy to: AUTOMATIC\n'
        'Setting subscription liveliness policy to: MANUAL_BY_TOPIC\n',
        {'liveliness': LivelinessPolicy.AUTOMATIC},
        {'liveliness': LivelinessPolicy.MANUAL_BY_TOPIC}),
    'liveliness_lease_duration': (
        'Liveliness lease duration incompatibility selected.\n'
        'Incompatibility condition: publisher liveliness lease duration >subscription '
        'liveliness lease duration.\n'
        'Setting publisher liveliness lease duration to: 2 seconds\n'
        'Setting subscription liveliness lease duration to: 1 second\n',
        {'liveliness_lease_duration': Duration(seconds=2)},
        {'liveliness_lease_duration': Duration(seconds=1)}),
    'reliability': (
        'Reliability incompatibility selected.\n'
        'Incompatibility condition: publisher reliability < subscripition reliability.\n'
        'Setting publisher reliability to: BEST_EFFORT\n'
        'Setting subscription reliability to: RELIABLE\n',
        {'reliability': ReliabilityPolicy.BEST_EFFORT},
        {'reliability': ReliabilityPolicy.RELIABLE}),
}


def get_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser()
    parser.add_argument('incompatible_qos_policy_name', type=str, choices=list(INCOMPATIBLE),
                        help='The QoS Policy that should be incompatible between the publisher '
                        'and subscription.')
    return parser


def log_incompatible(side: str, what: str):
    return lambda event: get_logger(side).info(
        f'{what} incompatible qos - total {event.total_count} delta '
        f'{event.total_count_change} last_policy_kind: {event.last_policy_kind}')


def main() -> int:
    args = get_parser().parse_args()
    text, publisher_qos, subscription_qos = INCOMPATIBLE[args.incompatible_qos_policy_name]
    print(text, flush=True)
    talker: list[Talker] = []

    def nodes(_executor):
        try:
            talker.append(Talker(TOPIC, QoSProfile(depth=10, **publisher_qos),
                                 PublisherEventCallbacks(incompatible_qos=log_incompatible(
                                     'talker', 'Offered')), publish_count=NUM_MSGS))
            listener = Listener(TOPIC, QoSProfile(depth=10, **subscription_qos),
                                SubscriptionEventCallbacks(incompatible_qos=log_incompatible(
                                    'listener', 'Requested')))
        except UnsupportedEventTypeError as error:
            print(f'\n{error}\n\nPlease try this demo using a different RMW implementation')
            raise SystemExit(1) from None
        return [listener, talker[0]]
    return run(nodes, done=lambda: talker[0].publish_count >= NUM_MSGS)


if __name__ == '__main__':
    sys.exit(main())
