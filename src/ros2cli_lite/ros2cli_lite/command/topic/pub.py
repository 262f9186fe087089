"""ros2 topic pub: Publish a message to a topic."""

from __future__ import annotations

import argparse
import time

from ros2cli_lite.qos import add_qos_arguments

HELP = 'Publish a message to a topic'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('topic_name', help="Name of the ROS topic to publish to (e.g. '/chatter')")
    parser.add_argument('message_type', help="Type of the ROS message (e.g. 'std_msgs/String')")
    parser.add_argument('values', nargs='?', default='{}',
                        help="Values to fill the message with in YAML format (e.g. 'data: Hello "
                        "World'), otherwise the message will be published with default values")
    parser.add_argument('-r', '--rate', metavar='N', type=float, default=1.0,
                        help='Publishing rate in Hz (default: 1)')
    parser.add_argument('-p', '--print', metavar='N', type=int, default=1,
                        help='Only print every N-th published message (default: 1)')
    group = parser.add_mutually_exclusive_group()
    group.add_argument('-1', '--once', action='store_true',
                       help='Publish one message and exit')
    group.add_argument('-t', '--times', type=int, default=0,
                       help='Publish this number of times and then exit')
    parser.add_argument('-w', '--wait-matching-subscriptions', type=int, default=None,
                        help='Wait until finding the specified number of matching subscriptions '
                        '(default: 1 with --once/--times, else 0)')
    parser.add_argument('--max-wait-time-secs', type=float, default=None,
                        help='Stop waiting for matching subscriptions after this many seconds')
    parser.add_argument('--keep-alive', metavar='N', type=float, default=0.1,
                        help='Keep publishing node alive for N seconds after the last msg '
                        '(default: 0.1)')
    parser.add_argument('-n', '--node-name', help='Name of the created publishing node')
    add_qos_arguments(parser, 'publish', 'default')


def runs_in_daemon(args: argparse.Namespace) -> bool:
    """With --once or --times it publishes a fixed number of messages and exits: the daemon may run
    it for the CLI (daemon/proxy.py)."""
    return bool(args.once or args.times)


def main(args: argparse.Namespace) -> int | str:
    from ros2cli_lite.api import import_type
    from ros2cli_lite.convert import populate
    from ros2cli_lite.node import cli_node, spin_once
    from ros2cli_lite.qos import publisher_events, qos_profile_from_args
    try:
        msg_type = import_type(args.message_type, 'msg')
    except ValueError:
        return 'The passed message type is invalid'
    if args.rate <= 0:
        return 'rate must be greater than zero'
    stamps: list = []  # fields given as `header: auto` / `stamp: now`, set at each publication
    msg = populate(msg_type(), args.values, stamps)
    times = 1 if args.once else args.times
    wait_for = args.wait_matching_subscriptions
    if wait_for is None:
        wait_for = 1 if times else 0
    with cli_node(args.node_name, spin_time=args.spin_time) as node:
        publisher = node.create_publisher(
            msg_type, args.topic_name, qos_profile_from_args(args),
            event_callbacks=publisher_events(node, args.topic_name))
        start = time.monotonic()
        last_note = None
        while publisher.get_subscription_count() < wait_for:
            now = time.monotonic()
            if args.max_wait_time_secs is not None and now - start > args.max_wait_time_secs:
                return (f'Timed out waiting for subscriptions on {args.topic_name} after '
                        f'{args.max_wait_time_secs:g} s')
            if last_note is None or now - last_note >= 1.0:
                print(f'Waiting for at least {wait_for} matching subscription(s)...', flush=True)
                last_note = now
            spin_once(node, 0.05)
        print('publisher: beginning loop', flush=True)
        count = 0
        period = 1.0 / args.rate
        next_time = time.monotonic()
        while True:
            if stamps:
                now = node.get_clock().now().to_msg()
                for stamp in stamps:
                    stamp(now)
            publisher.publish(msg)
            count += 1
            if args.print and count % args.print == 0:
                print(f'publishing #{count}: {msg!r}\n', flush=True)
            if times and count >= times:
                break
            next_time += period
            while time.monotonic() < next_time:
                spin_once(node, max(0.0, min(0.05, next_time - time.monotonic())))
        end = time.monotonic() + args.keep_alive
        while time.monotonic() < end:
            spin_once(node, max(0.0, min(0.05, end - time.monotonic())))
    return 0
