"""ros2topic's API: what the `ros2 topic` verbs share, and upstream's ros2topic.api names
(`get_topic_names_and_types`, `get_msg_class`, `qos_profile_from_short_keys`, the argcomplete
completers) for code written against ros2cli (fixture nodes, rqt plugins, scripts).

`node` is any rclpy node (upstream's NodeStrategy node answers the same graph queries). The
completers take argcomplete's `parsed_args`; they ask the daemon unless `--no-daemon` was given.
"""

from __future__ import annotations

import argparse
import copy
import time
from typing import Any

from ros2cli.names import is_hidden
from ros2cli.verb_context import CliError, VerbContext

# add_qos_arguments: upstream's ros2topic.api name, re-exported.
from ros2topic.api.qos import add_qos_arguments as add_qos_arguments
from ros2topic.api.qos import configure_profile

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


def query_graph(args: argparse.Namespace, ready=None, *, context: VerbContext):
    from ros2cli.graph import graph_source
    with graph_source(not args.no_daemon, args.spin_time, context) as source:
        return source.graph(ready=ready)


def lookup(node, name: str, include_hidden: bool, settle: float = 0.2,
            spin_time: float | None = None, *, context: VerbContext) -> list[str] | None:
    from ros2cli.node.discovery import wait_for_graph

    def types():
        return dict(topics(node, include_hidden)).get(name)
    wait_for_graph(
        node, ready=lambda: types() is not None, settle=settle, bound=spin_time, context=context
    )
    return types()


def lookup_now(
    node, name: str, spin_time: float | None = None, *, context: VerbContext
) -> list[str] | None:
    """The types of topic `name`, without waiting for it to appear (as ros2cli's echo): None
    once the node has met every participant on this host and their endpoints are known."""
    from ros2cli.node.discovery import wait_for_graph
    from ros2cli.node.participants import everyone_met

    def types():
        return dict(topics(node, True)).get(name)

    # Where the participants cannot be counted, the usual bounded wait for the name.
    wait_for_graph(
        node,
        ready=lambda: types() is not None or everyone_met(node) is True,
        settle=0.2,
        bound=spin_time,
        context=context,
    )
    return types()


def daemon_lookup(name: str, spin_time: float | None = None) -> tuple[list[str], int] | None:
    """(the types, the publisher count) of topic `name` in the daemon's graph (started if need
    be), waiting briefly (`spin_time`, else 0.3 s) for a publisher that has only just started."""
    from ros2cli.graph import graph_source

    def types(graph):
        return dict(graph.topics(True)).get(name)

    with graph_source(True, spin_time) as source:
        graph = source.graph(
            ready=lambda g: types(g) is not None, bound=0.3 if spin_time is None else spin_time
        )
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
        raise CliError(f'--filter: {expression!r} is no Python expression: {error.msg}') from None

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


def wait_for_type(node, topic: str, spin_time: float | None = None, *, context: VerbContext):
    """The message class of `topic`, waiting (with one warning) until it is published."""
    from ros2cli.interface_types import import_type
    from ros2cli.node.direct import spin_once

    found = lookup(node, topic, True, settle=0.2, spin_time=spin_time, context=context)
    warned = False
    while found is None:
        if not warned:
            print(
                f'WARNING: topic [{topic}] does not appear to be published yet', file=context.stderr
            )
            warned = True
        spin_once(node, 0.2, context)
        found = dict(topics(node, True)).get(topic)
    try:
        return import_type(found[0], 'msg')
    except ValueError:
        raise CliError(f"The message type '{found[0]}' is invalid") from None


def report_every_second(node, report, context: VerbContext) -> None:
    """Spin `node` until Ctrl-C, calling report() once a second of the node's clock (ros2cli's
    1 s timer: with -s, simulated seconds, so reports fall on the simulated clock's ticks)."""
    from ros2cli.node.direct import spin_once

    node.create_timer(1.0, report)
    while True:
        spin_once(node, 0.1, context)


# Upstream's names


def get_topic_names_and_types(
    *, node: Any, include_hidden_topics: bool = False
) -> list[tuple[str, list[str]]]:
    return topics(node, include_hidden_topics)


def get_topic_names(*, node: Any, include_hidden_topics: bool = False) -> list[str]:
    return [name for name, _ in topics(node, include_hidden_topics)]


def get_msg_class(
    node: Any, topic: str, blocking: bool = False, include_hidden_topics: bool = False
) -> Any:
    """The message class of `topic`, or None (after a warning) when it is not published; with
    `blocking`, wait (polling every 0.1 s) until it is, or the node's context shuts down."""
    msg_class = _msg_class(node, topic, include_hidden_topics)
    if msg_class is not None:
        return msg_class
    print(f'WARNING: topic [{topic}] does not appear to be published yet')
    while blocking and node.context.ok():
        time.sleep(0.1)
        msg_class = _msg_class(node, topic, include_hidden_topics)
        if msg_class is not None:
            return msg_class
    return None


def _msg_class(node: Any, topic: str, include_hidden_topics: bool) -> Any:
    from rclpy.exceptions import InvalidTopicNameException
    from rclpy.expand_topic_name import expand_topic_name
    from rclpy.validate_full_topic_name import validate_full_topic_name
    from rosidl_runtime_py.utilities import get_message

    try:
        name = expand_topic_name(topic, node.get_name(), node.get_namespace())
        validate_full_topic_name(name)
    except (ValueError, InvalidTopicNameException) as error:
        raise RuntimeError(error) from None
    found = dict(topics(node, include_hidden_topics)).get(name)
    if found is None:
        return None
    if len(found) > 1:
        raise RuntimeError(
            f"Cannot echo topic '{topic}', as it contains more than one type: [{', '.join(found)}]"
        )
    try:
        return get_message(found[0])
    except (AttributeError, ModuleNotFoundError, ValueError):
        raise RuntimeError(f"The message type '{found[0]}' is invalid") from None


def profile_configure_short_keys(
    profile: Any = None,
    reliability: str | None = None,
    durability: str | None = None,
    depth: int | None = None,
    history: str | None = None,
    liveliness: str | None = None,
    liveliness_lease_duration_s: float | None = None,
) -> None:
    """Set the policies given by their short keys on `profile` (in place; a depth of 0 or None
    keeps the profile's, as upstream)."""
    configure_profile(
        profile,
        reliability=reliability,
        durability=durability,
        depth=depth or None,
        history=history,
        liveliness=liveliness,
        lease_seconds=liveliness_lease_duration_s or None,
    )


def qos_profile_from_short_keys(
    preset_profile: str,
    reliability: str | None = None,
    durability: str | None = None,
    depth: int | None = None,
    history: str | None = None,
    liveliness: str | None = None,
    liveliness_lease_duration_s: float | None = None,
) -> Any:
    """The preset named `preset_profile` (e.g. 'sensor_data') with the given policies."""
    from rclpy.qos import QoSPresetProfiles

    # A copy: rclpy's presets are shared objects.
    profile = copy.copy(QoSPresetProfiles.get_from_short_key(preset_profile))
    profile_configure_short_keys(
        profile, reliability, durability, depth, history, liveliness, liveliness_lease_duration_s
    )
    return profile


def _graph_topics(
    parsed_args: argparse.Namespace, include_hidden: bool
) -> list[tuple[str, list[str]]]:
    from ros2cli.graph import graph_source

    use_daemon = not getattr(parsed_args, 'no_daemon', False)
    with graph_source(use_daemon, getattr(parsed_args, 'spin_time', None)) as source:
        return source.graph().topics(include_hidden)


class TopicNameCompleter:
    """Callable returning the topic names (argcomplete completer)."""

    def __init__(self, *, include_hidden_topics_key: str | None = None) -> None:
        self.include_hidden_topics_key = include_hidden_topics_key

    def __call__(self, prefix: str, parsed_args: argparse.Namespace, **kwargs: Any) -> list[str]:
        hidden = bool(
            self.include_hidden_topics_key
            and getattr(parsed_args, self.include_hidden_topics_key, False)
        )
        return [name for name, _ in _graph_topics(parsed_args, hidden)]


def message_type_completer(**kwargs: Any) -> list[str]:
    """Every message type installed, as 'pkg/msg/Name'."""
    from rosidl_runtime_py import get_message_interfaces

    interfaces = get_message_interfaces()
    return [
        f'{package}/{name}'
        for package in sorted(interfaces)
        for name in sorted(interfaces[package])
    ]


class TopicTypeCompleter:
    """Callable returning the type of the topic already given, else every message type."""

    def __init__(self, *, topic_name_key: str | None = None) -> None:
        self.topic_name_key = topic_name_key

    def __call__(self, prefix: str, parsed_args: argparse.Namespace, **kwargs: Any) -> list[str]:
        if self.topic_name_key is not None:
            topic = getattr(parsed_args, self.topic_name_key)
            found = dict(_graph_topics(parsed_args, True)).get(topic)
            if found:
                return found
        return message_type_completer()


class TopicMessagePrototypeCompleter:
    """Callable returning a default message of the given type, as YAML."""

    def __init__(self, *, topic_type_key: str | None = None) -> None:
        self.topic_type_key = topic_type_key

    def __call__(self, prefix: str, parsed_args: argparse.Namespace, **kwargs: Any) -> list[str]:
        from rosidl_runtime_py.utilities import get_message

        from rosidl_runtime_py import message_to_yaml

        message = get_message(getattr(parsed_args, self.topic_type_key))
        return [message_to_yaml(message())]
