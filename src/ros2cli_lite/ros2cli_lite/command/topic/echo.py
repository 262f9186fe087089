"""ros2 topic echo: Output messages from a topic."""

from __future__ import annotations

import argparse
import sys
import time

from ros2cli_lite.command.topic.api import lookup
from ros2cli_lite.qos import add_qos_arguments

HELP = 'Output messages from a topic'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('topic_name', help="Name of the ROS topic to listen to (e.g. '/chatter')")
    parser.add_argument('message_type', nargs='?',
                        help="Type of the ROS message (e.g. 'std_msgs/msg/String')")
    add_qos_arguments(parser, 'subscribe', 'sensor_data')
    parser.add_argument('--once', action='store_true', help='Print the first message received and '
                        'then exit')
    parser.add_argument('--field', type=str, default=None,
                        help="Echo a selected field of a message, e.g. 'linear.x'")
    parser.add_argument('--flow-style', action='store_true', help='Print collections in the block '
                        'style (not available with csv format)')
    parser.add_argument('--timeout', type=float, default=None,
                        help='Stop after this many seconds without a message (with --once)')


def runs_in_daemon(args: argparse.Namespace) -> bool:
    """With --once it prints one message and exits: the daemon may run it for the CLI
    (daemon/proxy.py)."""
    return args.once


def main(args: argparse.Namespace) -> int | str:
    from ros2cli_lite.api import import_type
    from ros2cli_lite.convert import to_yaml
    from ros2cli_lite.node import cli_node, spin_once
    from ros2cli_lite.qos import subscription_events, subscription_qos
    from rosidl_runtime_py import message_to_yaml
    fields = args.field.split('.') if args.field else []
    with cli_node(spin_time=args.spin_time) as node:
        if args.message_type:
            try:
                msg_type = import_type(args.message_type, 'msg')
            except ValueError:
                return 'The passed message type is invalid'
            lookup(node, args.topic_name, True, settle=0.2, spin_time=args.spin_time)
        else:
            found = lookup(node, args.topic_name, True, settle=0.2, spin_time=args.spin_time)
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
                text = message_to_yaml(value, flow_style=args.flow_style)
            elif isinstance(value, (list, tuple)) or type(value).__name__ in ('array', 'ndarray'):
                text = to_yaml(list(value), args.flow_style)
            else:
                text = f'{value}\n'
            sys.stdout.write(text + '---\n')
            sys.stdout.flush()
            state['count'] += 1

        node.create_subscription(msg_type, args.topic_name, callback,
                                 subscription_qos(node, args),
                                 event_callbacks=subscription_events(node, args.topic_name))
        deadline = None if args.timeout is None else time.monotonic() + args.timeout
        while not (args.once and state['count']) and state['error'] is None:
            if deadline is not None and time.monotonic() > deadline:
                return f'No message received on {args.topic_name} within {args.timeout:g} s'
            spin_once(node, 0.1)
        if state['error']:
            return state['error']
    return 0
