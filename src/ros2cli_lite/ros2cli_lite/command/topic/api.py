"""What the verbs of `ros2 topic` share."""

from __future__ import annotations

import argparse
import sys

from ros2cli_lite.api import CliError, is_hidden

HIDDEN = '--include-hidden-topics'


def positive_int(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value <= 0:
        raise argparse.ArgumentTypeError(f'value must be a positive integer, got {text!r}')
    return value


def positive_float(text: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f'Expects a floating point number, got {text!r}') \
            from None
    if not value > 0.0:
        raise argparse.ArgumentTypeError(f'Value must be positive, got {text!r}')
    return value


def includes_hidden(args: argparse.Namespace) -> bool:
    return bool(args.include_hidden_topics or args.include_hidden_topics_verb)


def topics(node, include_hidden: bool) -> list[tuple[str, list[str]]]:
    return [(name, types) for name, types in node.get_topic_names_and_types()
            if include_hidden or not is_hidden(name)]


def query_graph(args: argparse.Namespace, ready=None):
    from ros2cli_lite.graph import graph_source
    with graph_source(not args.no_daemon, args.spin_time) as source:
        return source.graph(ready=ready)


def lookup(node, name: str, include_hidden: bool, settle: float = 0.2,
            spin_time: float | None = None) -> list[str] | None:
    from ros2cli_lite.node import wait_for_graph

    def types():
        return dict(topics(node, include_hidden)).get(name)
    wait_for_graph(node, ready=lambda: types() is not None, settle=settle, bound=spin_time)
    return types()


def lookup_now(node, name: str, spin_time: float | None = None) -> list[str] | None:
    """The types of topic `name`, without waiting for it to appear (as ros2cli's echo): None
    once the node has met every participant on this host and their endpoints are known."""
    from ros2cli_lite.node import wait_for_graph
    from ros2cli_lite.participants import everyone_met

    def types():
        return dict(topics(node, True)).get(name)
    # Where the participants cannot be counted, the usual bounded wait for the name.
    wait_for_graph(node, ready=lambda: types() is not None or everyone_met(node) is True,
                   settle=0.2, bound=spin_time)
    return types()


def daemon_lookup(name: str, spin_time: float | None = None) -> tuple[list[str], int] | None:
    """(the types, the publisher count) of topic `name` in the daemon's graph (started if need
    be), waiting briefly (`spin_time`, else 0.3 s) for a publisher that has only just started."""
    from ros2cli_lite.graph import graph_source

    def types(graph):
        return dict(graph.topics(True)).get(name)
    with graph_source(True, spin_time) as source:
        graph = source.graph(ready=lambda g: types(g) is not None,
                             bound=0.3 if spin_time is None else spin_time)
    found = types(graph)
    return None if found is None else (found, graph.topic_counts(name)[0])


def message_filter(expression: str | None):
    """ros2cli's `--filter EXPR`: a predicate evaluating the Python expression with the message
    as `m` (and Python's builtins), or None without an expression."""
    if not expression:
        return None
    try:
        code = compile(expression, '<filter>', 'eval')
    except SyntaxError as error:
        raise CliError(f'--filter: {expression!r} is no Python expression: {error.msg}') \
            from None

    def keep(m) -> bool:
        try:
            return bool(eval(code, {}, {'m': m}))
        except Exception as error:  # the user's expression, on this message
            raise CliError(f'--filter: {expression!r} failed: {error!r}') from None
    return keep


def apply_sim_time(node, args: argparse.Namespace) -> None:
    """`-s/--use-sim-time`: the node's clock follows /clock (rclpy's TimeSource switches when
    the parameter is set)."""
    if getattr(args, 'use_sim_time', False):
        from rclpy.parameter import Parameter
        node.set_parameters([Parameter('use_sim_time', value=True)])


def wait_for_type(node, topic: str, spin_time: float | None = None):
    """The message class of `topic`, waiting (with one warning) until it is published."""
    from ros2cli_lite.api import import_type
    from ros2cli_lite.node import spin_once
    found = lookup(node, topic, True, settle=0.2, spin_time=spin_time)
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


def report_every_second(node, report) -> None:
    """Spin `node` until Ctrl-C, calling report() once a second of the node's clock (ros2cli's
    1 s timer: with -s, simulated seconds, so reports fall on the simulated clock's ticks)."""
    from ros2cli_lite.node import spin_once
    node.create_timer(1.0, report)
    while True:
        spin_once(node, 0.1)
