"""ros2 topic pub: Publish a message to a topic."""

from __future__ import annotations

import argparse
import sys
import time

from ros2cli.echo_options import unsigned_int
from ros2cli.verb_context import VerbContext

from ros2topic.api import positive_float
from ros2topic.api.qos import add_qos_arguments
from ros2topic.verb import VerbExtension

HELP = 'Publish a message to a topic'
WAIT_STEP = 0.1  # seconds between two checks for matching subscriptions


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('topic_name', help="Name of the ROS topic to publish to (e.g. '/chatter')")
    parser.add_argument('message_type', help="Type of the ROS message (e.g. 'std_msgs/String')")
    values = parser.add_mutually_exclusive_group()
    values.add_argument('values', nargs='?', default='{}',
                        help="Values to fill the message with in YAML format (e.g. 'data: Hello "
                        "World'), otherwise the message will be published with default values")
    values.add_argument('--stdin', action='store_true', help='Read values from standard input')
    parser.add_argument('-r', '--rate', metavar='N', type=positive_float, default=1.0,
                        help='Publishing rate in Hz (default: 1)')
    parser.add_argument('-p', '--print', metavar='N', type=int, default=1,
                        help='Only print every N-th published message (default: 1)')
    group = parser.add_mutually_exclusive_group()
    group.add_argument('-1', '--once', action='store_true',
                       help='Publish one message and exit')
    group.add_argument('-t', '--times', type=unsigned_int, default=0,
                       help='Publish this number of times and then exit')
    parser.add_argument('-w', '--wait-matching-subscriptions', type=unsigned_int,
                        default=None,
                        help='Wait until finding the specified number of matching subscriptions. '
                        'Defaults to 1 when using "-1"/"--once"/"--times", otherwise defaults '
                        'to 0.')
    parser.add_argument('--max-wait-time-secs', type=positive_float, default=None,
                        help='This sets the maximum wait time in seconds if '
                        '--wait-until-matching-subscriptions is set. By default, this flag is '
                        'not set meaning the subscriber will wait endlessly.')
    parser.add_argument('--keep-alive', metavar='N', type=positive_float, default=0.1,
                        help='Keep publishing node alive for N seconds after the last msg '
                        '(default: 0.1)')
    parser.add_argument('-n', '--node-name', help='Name of the created publishing node')
    add_qos_arguments(parser, 'publish', 'default')


def runs_in_daemon(args: argparse.Namespace) -> bool:
    """With --once or --times it publishes a fixed number of messages and exits: the daemon may run
    it for the CLI (ros2cli.daemon.verb_host)."""
    return bool(args.once or args.times) and not args.stdin


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from ros2cli.interface_types import import_type
    from ros2cli.message_yaml import populate
    from ros2cli.node.direct import cli_node

    from ros2topic.api import apply_sim_time
    from ros2topic.api.qos import publisher_events, qos_profile_from_args
    try:
        msg_type = import_type(args.message_type, 'msg')
    except ValueError:
        return 'The passed message type is invalid'
    stamps: list = []  # fields given as `header: auto` / `stamp: now`, set at each publication
    msg = populate(msg_type(), sys.stdin.read() if args.stdin else args.values, stamps)
    times = 1 if args.once else args.times
    wait_for = args.wait_matching_subscriptions
    if wait_for is None:
        wait_for = 1 if times else 0
    if wait_for == 0 and args.max_wait_time_secs is not None:
        return ('--max-wait-time-secs option is only effective with '
                '--wait-matching-subscriptions, --once or --times')
    with cli_node(context, args.node_name, spin_time=args.spin_time) as node:
        apply_sim_time(node, args)
        publisher = node.create_publisher(
            msg_type, args.topic_name, qos_profile_from_args(args),
            event_callbacks=publisher_events(node, args.topic_name, context))
        # ros2cli's wait: checks every 0.1 s, a note every second, the limit counted in checks.
        start = time.monotonic()
        checks = 0
        while publisher.get_subscription_count() < wait_for:
            if checks % 10 == 0:
                print(
                    f'Waiting for at least {wait_for} matching subscription(s)...',
                    flush=True,
                    file=context.stdout,
                )
            if (
                args.max_wait_time_secs is not None
                and checks * WAIT_STEP >= args.max_wait_time_secs - 1e-9
            ):
                return (
                    f'Timed out waiting for subscribers: Expected {wait_for} subcribers but '
                    f'only got {publisher.get_subscription_count()} subscribers'
                )
            checks += 1
            _spin_until(node, time.monotonic, start + checks * WAIT_STEP, context)
        print('publisher: beginning loop', flush=True, file=context.stdout)
        # The period in the node's clock: with -s, in simulated time.
        clock = node.get_clock()
        period = int(1e9 / args.rate)
        count = 0
        next_time = clock.now().nanoseconds
        while True:
            if stamps:
                now = clock.now().to_msg()
                for stamp in stamps:
                    stamp(now)
            publisher.publish(msg)
            count += 1
            if args.print and count % args.print == 0:
                print(f'publishing #{count}: {msg!r}\n', flush=True, file=context.stdout)
            if times and count >= times:
                break
            next_time += period
            _spin_until(node, lambda: clock.now().nanoseconds, next_time, context)
        _spin_until(node, time.monotonic, time.monotonic() + args.keep_alive, context)
    return 0


def _spin_until(node, now, deadline: float, context: VerbContext) -> None:
    """Spin `node` until the clock `now()` reads `deadline` (any unit)."""
    from ros2cli.node.direct import spin_once

    while now() < deadline:
        spin_once(node, 0.01, context)


class PubVerb(VerbExtension):
    """Upstream's class of this verb, for code that drives it from Python."""
