"""ros2 topic: list, type, find, info, echo, pub, hz, bw, delay."""

from __future__ import annotations

import argparse
import itertools
import math
import sys
import time

from ros2cli_lite.api import add_graph_verb, is_hidden, print_names

HIDDEN = '--include-hidden-topics'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(HIDDEN, action='store_true', help='Consider hidden topics as well')
    verbs = parser.add_subparsers(title='Commands', metavar='Call')

    def verb(name: str, func, help_text: str) -> argparse.ArgumentParser:
        return add_graph_verb(verbs, name, func, help_text, HIDDEN, 'include_hidden_topics_verb')

    p = verb('list', list_verb, 'Output a list of available topics')
    p.add_argument('-t', '--show-types', action='store_true',
                   help='Additionally show the topic type')
    p.add_argument('-c', '--count-topics', action='store_true',
                   help='Only display the number of topics discovered')
    p.add_argument('-v', '--verbose', action='store_true',
                   help='List full details about each topic')
    p = verb('type', type_verb, 'Print a topic\'s type')
    p.add_argument('topic_name', help="Name of the ROS topic to get type (e.g. '/chatter')")
    p = verb('find', find_verb, 'Output a list of available topics of a given type')
    p.add_argument('topic_type', help="Name of the ROS topic type to filter for (e.g. "
                   "'std_msg/msg/String')")
    p.add_argument('-c', '--count-topics', action='store_true',
                   help='Only display the number of topics discovered')
    p = verb('info', info_verb, 'Print information about a topic')
    p.add_argument('topic_name', help="Name of the ROS topic to get info (e.g. '/chatter')")
    p.add_argument('-v', '--verbose', action='store_true',
                   help='Prints detailed information like the node name, node namespace, topic '
                   'type, GUID and QoS Profile of the publishers and subscribers to this topic')
    p = verb('echo', echo_verb, 'Output messages from a topic')
    p.add_argument('topic_name', help="Name of the ROS topic to listen to (e.g. '/chatter')")
    p.add_argument('message_type', nargs='?',
                   help="Type of the ROS message (e.g. 'std_msgs/msg/String')")
    p.add_argument('--once', action='store_true', help='Print the first message received and '
                   'then exit')
    p.add_argument('--field', type=str, default=None,
                   help="Echo a selected field of a message, e.g. 'linear.x'")
    p.add_argument('--flow-style', action='store_true', help='Print collections in the block '
                   'style (not available with csv format)')
    p.add_argument('--timeout', type=float, default=None,
                   help='Stop after this many seconds without a message (with --once)')
    p = verb('pub', pub_verb, 'Publish a message to a topic')
    p.add_argument('topic_name', help="Name of the ROS topic to publish to (e.g. '/chatter')")
    p.add_argument('message_type', help="Type of the ROS message (e.g. 'std_msgs/String')")
    p.add_argument('values', nargs='?', default='{}',
                   help="Values to fill the message with in YAML format (e.g. 'data: Hello "
                   "World'), otherwise the message will be published with default values")
    p.add_argument('-r', '--rate', metavar='N', type=float, default=1.0,
                   help='Publishing rate in Hz (default: 1)')
    p.add_argument('-p', '--print', metavar='N', type=int, default=1,
                   help='Only print every N-th published message (default: 1)')
    group = p.add_mutually_exclusive_group()
    group.add_argument('-1', '--once', action='store_true',
                       help='Publish one message and exit')
    group.add_argument('-t', '--times', type=int, default=0,
                       help='Publish this number of times and then exit')
    p.add_argument('-w', '--wait-matching-subscriptions', type=int, default=None,
                   help='Wait until finding the specified number of matching subscriptions '
                   '(default: 1 with --once/--times, else 0)')
    p.add_argument('--max-wait-time-secs', type=float, default=None,
                   help='Stop waiting for matching subscriptions after this many seconds')
    p.add_argument('--keep-alive', metavar='N', type=float, default=0.1,
                   help='Keep publishing node alive for N seconds after the last msg '
                   '(default: 0.1)')
    p.add_argument('-n', '--node-name', help='Name of the created publishing node')
    p = verb('hz', hz_verb, 'Print the average publishing rate to screen')
    p.add_argument('topic_name', help="Name of the ROS topic to listen to (e.g. '/chatter')")
    p.add_argument('--window', '-w', type=_positive_int, default=10000,
                   help='window size, in # of messages, for calculating rate (default: 10000)')
    p = verb('bw', bw_verb, 'Display bandwidth used by topic')
    p.add_argument('topic_name', help='Topic name to monitor for bandwidth utilization')
    p.add_argument('--window', '-w', type=_positive_int, default=100, metavar='WINDOW',
                   help='maximum window size, in # of messages, for calculating rate '
                   '(default: 100)')
    p = verb('delay', delay_verb, 'Display delay of topic from timestamp in header')
    p.add_argument('topic_name', help='Topic name to calculate the delay for')
    p.add_argument('--window', '-w', type=_positive_int, default=10000,
                   help='window size, in # of messages, for calculating rate (default: 10000)')


def _positive_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value <= 0:
        raise argparse.ArgumentTypeError(f'value must be a positive integer, got {text!r}')
    return value


def _include_hidden(args: argparse.Namespace) -> bool:
    return bool(args.include_hidden_topics or args.include_hidden_topics_verb)


def topics(node, include_hidden: bool) -> list[tuple[str, list[str]]]:
    return [(name, types) for name, types in node.get_topic_names_and_types()
            if include_hidden or not is_hidden(name)]


def _plural(count: int, word: str) -> str:
    return f'{count} {word}{"s" if count > 1 else ""}'


def _graph(args: argparse.Namespace, ready=None):
    from ros2cli_lite.graph import graph_source
    with graph_source(not args.no_daemon) as source:
        return source.graph(ready=ready)


def list_verb(args: argparse.Namespace) -> int:
    graph = _graph(args)
    found = graph.topics(_include_hidden(args))
    if args.count_topics:
        print(len(found))
    elif args.verbose:
        for title, index, word in (('Published topics:', 0, 'publisher'),
                                   ('Subscribed topics:', 1, 'subscriber')):
            print(title)
            for name, types in found:
                n = graph.topic_counts(name)[index]
                if n:
                    print(f' * {name} [{", ".join(types)}] {_plural(n, word)}')
            print()
    else:
        for name, types in found:
            print(f'{name} [{", ".join(types)}]' if args.show_types else name)
    return 0


def _lookup(node, name: str, include_hidden: bool, settle: float = 0.2) -> list[str] | None:
    from ros2cli_lite.api import wait_for_graph

    def types():
        return dict(topics(node, include_hidden)).get(name)
    wait_for_graph(node, ready=lambda: types() is not None, settle=settle)
    return types()


def type_verb(args: argparse.Namespace) -> int:
    hidden = _include_hidden(args)
    graph = _graph(args, ready=lambda g: args.topic_name in dict(g.topics(hidden)))
    found = dict(graph.topics(hidden)).get(args.topic_name)
    if found is None:
        return 1
    for topic_type in found:
        print(topic_type)
    return 0


def find_verb(args: argparse.Namespace) -> int:
    print_names([name for name, types in _graph(args).topics(_include_hidden(args))
                 if args.topic_type in types], args.count_topics)
    return 0


def info_verb(args: argparse.Namespace) -> int | str:
    from ros2cli_lite.graph import graph_source
    end = '\n\n' if args.verbose else '\n'
    with graph_source(not args.no_daemon) as source:
        graph = source.graph(ready=lambda g: args.topic_name in dict(g.topics(True)))
        found = dict(graph.topics(True)).get(args.topic_name)
        if found is None:
            return f"Unknown topic '{args.topic_name}'"
        publishers, subscribers = source.endpoints(args.topic_name) if args.verbose else ([], [])
    publisher_count, subscriber_count = graph.topic_counts(args.topic_name)
    print(f'Type: {found[0] if len(found) == 1 else found}', end=end)
    print(f'Publisher count: {publisher_count}', end=end)
    for text in publishers:
        print(text, end=end)
    print(f'Subscription count: {subscriber_count}', end=end)
    for text in subscribers:
        print(text, end=end)
    return 0


def _echo_qos(node, topic: str):
    from rclpy.qos import DurabilityPolicy, ReliabilityPolicy, qos_profile_sensor_data
    qos = qos_profile_sensor_data
    infos = node.get_publishers_info_by_topic(topic)
    if infos:
        from copy import copy
        qos = copy(qos)
        if all(i.qos_profile.reliability == ReliabilityPolicy.RELIABLE for i in infos):
            qos.reliability = ReliabilityPolicy.RELIABLE
        if all(i.qos_profile.durability == DurabilityPolicy.TRANSIENT_LOCAL for i in infos):
            qos.durability = DurabilityPolicy.TRANSIENT_LOCAL
    return qos


def echo_verb(args: argparse.Namespace) -> int | str:
    from ros2cli_lite.api import cli_node, import_type, message_to_yaml, spin_once, to_yaml
    fields = args.field.split('.') if args.field else []
    with cli_node() as node:
        if args.message_type:
            try:
                msg_type = import_type(args.message_type, 'msg')
            except ValueError:
                return 'The passed message type is invalid'
            _lookup(node, args.topic_name, True, settle=0.2)
        else:
            found = _lookup(node, args.topic_name, True, settle=0.2)
            if found is None:
                print(f'WARNING: topic [{args.topic_name}] does not appear to be published yet',
                      file=sys.stderr)
                return 'Could not determine the type for the passed topic'
            try:
                msg_type = import_type(found[0], 'msg')
            except ValueError:
                return f"The message type '{found[0]}' is invalid"
        state = {'count': 0, 'error': None}

        def callback(msg) -> None:
            if args.once and state['count']:
                return
            value = msg
            for field in fields:
                try:
                    value = getattr(value, field)
                except AttributeError:
                    state['error'] = f"Invalid field '{args.field}': {type(value).__name__} has " \
                        f"no field '{field}'"
                    return
            if hasattr(value, 'get_fields_and_field_types'):
                text = message_to_yaml(value, args.flow_style)
            elif isinstance(value, (list, tuple)) or type(value).__name__ in ('array', 'ndarray'):
                text = to_yaml(list(value), args.flow_style)
            else:
                text = f'{value}\n'
            sys.stdout.write(text + '---\n')
            sys.stdout.flush()
            state['count'] += 1

        node.create_subscription(msg_type, args.topic_name, callback,
                                 _echo_qos(node, args.topic_name))
        deadline = None if args.timeout is None else time.monotonic() + args.timeout
        while not (args.once and state['count']) and state['error'] is None:
            if deadline is not None and time.monotonic() > deadline:
                return f'No message received on {args.topic_name} within {args.timeout:g} s'
            spin_once(node, 0.1)
        if state['error']:
            return state['error']
    return 0


def pub_verb(args: argparse.Namespace) -> int | str:
    from rclpy.qos import QoSProfile

    from ros2cli_lite.api import cli_node, import_type, populate, spin_once
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
    with cli_node(args.node_name) as node:
        publisher = node.create_publisher(msg_type, args.topic_name, QoSProfile(depth=10))
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


def _wait_for_type(node, topic: str):
    """The message class of `topic`, waiting (with one warning) until it is published."""
    from ros2cli_lite.api import CliError, import_type, spin_once
    found = _lookup(node, topic, True, settle=0.2)
    warned = False
    while found is None:
        if not warned:
            print(f'WARNING: topic [{topic}] does not appear to be published yet',
                  file=sys.stderr)
            warned = True
        spin_once(node, 0.2)
        found = dict(topics(node, True)).get(topic)
    try:
        return import_type(found[0], 'msg')
    except ValueError:
        raise CliError(f"The message type '{found[0]}' is invalid") from None


def hz_verb(args: argparse.Namespace) -> int | str:
    from rclpy.qos import qos_profile_sensor_data

    from ros2cli_lite.api import cli_node, spin_once
    with cli_node() as node:
        msg_type = _wait_for_type(node, args.topic_name)
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


def _size_text(count: float, scale: float) -> str:
    if scale == 1:
        return f'{count:.0f} B'
    return f'{count / scale:.2f} {"KB" if scale == 1e3 else "MB"}'


def bw_verb(args: argparse.Namespace) -> int | str:
    from collections import deque

    from rclpy.qos import qos_profile_sensor_data

    from ros2cli_lite.api import cli_node
    with cli_node() as node:
        msg_type = _wait_for_type(node, args.topic_name)
        clock = node.get_clock()
        window: deque[tuple[int, int]] = deque(maxlen=args.window)  # (ns received, bytes)

        def on_message(data: bytes) -> None:
            window.append((clock.now().nanoseconds, len(data)))

        node.create_subscription(msg_type, args.topic_name, on_message,
                                 qos_profile_sensor_data, raw=True)
        print(f'Subscribed to [{args.topic_name}]', flush=True)

        def report() -> None:
            if len(window) < 2:
                return
            elapsed = (clock.now().nanoseconds - window[0][0]) * 1e-9
            if elapsed <= 0:
                print('WARNING: time is reset!', file=sys.stderr)
                window.clear()
                return
            sizes = [size for _, size in window]
            rate = sum(sizes) / elapsed
            scale = 1 if rate < 1e3 else 1e3 if rate < 1e6 else 1e6
            mean, low, high = (_size_text(v, scale) for v in
                               (sum(sizes) / len(sizes), min(sizes), max(sizes)))
            print(f'{_size_text(rate, scale)}/s from {len(sizes)} messages\n'
                  f'\tMessage size mean: {mean} min: {low} max: {high}', flush=True)

        _report_every_second(node, report)


def delay_verb(args: argparse.Namespace) -> int | str:
    from collections import deque

    from rclpy.qos import qos_profile_sensor_data
    from rclpy.time import Time

    from ros2cli_lite.api import cli_node, type_name
    with cli_node() as node:
        msg_type = _wait_for_type(node, args.topic_name)
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
                print('no new messages', flush=True)
                return
            received['printed'] = received['count']
            n = len(delays)
            mean = sum(delays) / n
            std = math.sqrt(sum((d - mean) ** 2 for d in delays) / n)
            print(f'average delay: {mean * 1e-9:.3f}\n\tmin: {min(delays) * 1e-9:.3f}s '
                  f'max: {max(delays) * 1e-9:.3f}s std dev: {std * 1e-9:.5f}s window: {n}',
                  flush=True)

        _report_every_second(node, report)


def _report_every_second(node, report) -> None:
    """Spin `node` until Ctrl-C, calling report() once a second (ros2cli's 1 s timer)."""
    from ros2cli_lite.api import spin_once
    next_report = time.monotonic() + 1.0
    while True:
        spin_once(node, max(0.0, min(0.1, next_report - time.monotonic())))
        if time.monotonic() >= next_report:
            next_report += 1.0
            report()
