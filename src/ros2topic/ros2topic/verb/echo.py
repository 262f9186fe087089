"""ros2 topic echo: Output messages from a topic."""

from __future__ import annotations

import argparse
import time
from typing import Any

from ros2cli.echo_options import add_output_options, conversion_options
from ros2cli.verb_context import VerbContext

from ros2topic.api import lookup_now, message_filter, positive_float
from ros2topic.api.qos import add_qos_arguments
from ros2topic.verb import VerbExtension

HELP = 'Output messages from a topic'


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument('topic_name', help="Name of the ROS topic to listen to (e.g. '/chatter')")
    parser.add_argument('message_type', nargs='?',
                        help="Type of the ROS message (e.g. 'std_msgs/msg/String')")
    add_qos_arguments(parser, 'subscribe', 'sensor_data')
    parser.add_argument('--csv', action='store_true',
                        help='Output all recursive fields separated by commas (e.g. for '
                        'plotting). If --include-message-info is also passed, the following '
                        'fields are prepended: source_timestamp, received_timestamp, '
                        'publication_sequence_number, reception_sequence_number.')
    parser.add_argument('--field', type=str, default=None,
                        help="Echo a selected field of a message. Use '.' to select sub-fields. "
                        'For example, to echo the position field of a nav_msgs/msg/Odometry '
                        "message: 'ros2 topic echo /odom --field pose.pose.position'")
    add_output_options(parser)
    parser.add_argument('--no-lost-messages', action='store_true',
                        help="Don't report when a message is lost")
    parser.add_argument('--raw', action='store_true', help='Echo the raw binary representation')
    parser.add_argument('--filter', dest='filter_expr',
                        help='Python expression to filter messages that are printed. Expression '
                        'can use Python builtins as well as m (the message).')
    parser.add_argument('--once', action='store_true',
                        help='Print the first message received and then exit.')
    parser.add_argument('--timeout', metavar='N', type=positive_float, default=None,
                        help='Set a timeout in seconds for waiting')
    parser.add_argument('--include-message-info', '-i', action='store_true',
                        help='Shows the associated message info.')


def runs_in_daemon(args: argparse.Namespace) -> bool:
    """With --once it prints one message and exits: the daemon may run it for the CLI
    (ros2cli.daemon.verb_host)."""
    return args.once


class _Printer:
    """Turns each received message into ros2cli's output: YAML (or CSV, or the raw bytes)
    followed by `---`."""

    def __init__(self, args: argparse.Namespace, fields: list[str] | None,
                 context: VerbContext) -> None:
        self.args = args
        self.context = context
        self.fields = fields
        self.keep = message_filter(args.filter_expr)
        self.options = conversion_options(args)
        self.count = 0
        self.error: str | None = None

    def __call__(self, msg: Any, info: Any) -> None:
        if self.error is not None or (self.args.once and self.count):
            return
        value = msg
        for field in self.fields or ():
            try:
                value = getattr(value, field)
            except AttributeError as error:
                self.error = f"Invalid field '{'.'.join(self.fields)}': {error}"
                return
        if self.keep is not None and not self.keep(value):
            return
        self.count += 1
        self.context.stdout.write(self.text(value, info))
        self.context.stdout.flush()

    def text(self, value: Any, info: Any) -> str:
        import yaml

        from rosidl_runtime_py import message_to_csv, message_to_yaml

        with_info = self.args.include_message_info
        if not hasattr(value, '__slots__'):  # raw bytes or a selected non-message field
            head = f'---Got new message, message info:---\n{info}\n---Message data:---\n'
            return (head if with_info else '') + f'{value}\n---\n'
        if self.args.csv:
            line = message_to_csv(value, **self.options)
            if with_info:
                line = ','.join(str(item) for item in info.values()) + ',' + line
            return line + '\n'
        head = yaml.dump(info) + '---\n' if with_info else ''
        return head + message_to_yaml(value, flow_style=self.args.flow_style,
                                      **self.options) + '---\n'


def _lost(status: Any, context: VerbContext) -> None:
    print(f'A message was lost!!!\n\ttotal count change:{status.total_count_change}'
          f'\n\ttotal count: {status.total_count}', end='---\n', flush=True, file=context.stdout)


def _unknown_type(topic: str, context: VerbContext) -> str:
    # The warning on stdout, as ros2cli's print() (upstream's tests filter it from the output).
    print(f'WARNING: topic [{topic}] does not appear to be published yet', flush=True,
          file=context.stdout)
    return 'Could not determine the type for the passed topic'


def main(args: argparse.Namespace, context: VerbContext) -> int | str:
    from ros2cli.interface_types import import_type
    from ros2cli.node.direct import cli_node, spin_once

    from ros2topic.api import apply_sim_time, daemon_lookup
    from ros2topic.api.adaptive_subscription import AdaptiveSubscription
    from ros2topic.api.qos import policies_given

    fields = None
    if args.field is not None:
        fields = [name for name in args.field.split('.') if name]
        if not fields:
            return f"Invalid field value '{args.field}'"
    printer = _Printer(args, fields, context)
    type_name = args.message_type
    publishers = 0  # how many the daemon knows: ours waits (bounded) to know as many
    if type_name is None and not context.in_daemon and not args.no_daemon:
        # As ros2cli: the daemon's graph, asked before this process joins the graph itself.
        found = daemon_lookup(args.topic_name, args.spin_time)
        if found is None:
            return _unknown_type(args.topic_name, context)
        type_name, publishers = found[0][0], found[1]
    # With the type and the QoS given nothing is asked of the graph: subscribe at once.
    discover = type_name is None or not policies_given(args)
    with cli_node(context, discover=discover, spin_time=args.spin_time) as node:
        apply_sim_time(node, args)
        if type_name is None:
            found = lookup_now(node, args.topic_name, args.spin_time, context=context)
            if found is None:
                return _unknown_type(args.topic_name, context)
            type_name = found[0]
        try:
            msg_type = import_type(type_name, 'msg')
        except ValueError:
            return (
                'The passed message type is invalid'
                if args.message_type
                else f"The message type '{type_name}' is invalid"
            )
        if publishers and discover:
            _wait_for_publishers(node, args.topic_name, publishers, args.spin_time, context)
        subscription = AdaptiveSubscription(
            node,
            msg_type,
            args.topic_name,
            printer,
            args,
            context,
            raw=args.raw,
            message_lost=None if args.no_lost_messages else lambda status: _lost(status, context),
        )
        # --timeout ends the echo after that long, quietly, with or without messages.
        deadline = None if args.timeout is None else time.monotonic() + args.timeout
        while not (args.once and printer.count) and printer.error is None:
            if deadline is not None and time.monotonic() >= deadline:
                break
            spin_once(
                node,
                0.1 if deadline is None else max(0.0, min(0.1, deadline - time.monotonic())),
                context,
            )
            subscription.poll()
    return printer.error or 0


def _wait_for_publishers(
    node: Any, topic: str, count: int, spin_time: float | None, context: VerbContext
) -> None:
    """Until `node` knows `count` publishers of `topic` (their QoS decides the subscription's),
    for at most `spin_time` (else 2 s): a publisher's endpoints can reach a fresh node well
    after its participant. One seen later still counts (AdaptiveSubscription re-decides)."""
    from ros2cli.node.discovery import wait_until

    wait_until(
        lambda: len(node.get_publishers_info_by_topic(topic)) >= count,
        2.0 if spin_time is None else spin_time,
        context=context,
    )


class EchoVerb(VerbExtension):
    """Upstream's class of this verb, for code that drives it from Python."""
