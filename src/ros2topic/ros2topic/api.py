"""ros2topic.api as upstream names it, for code written against ros2cli (fixture nodes, rqt
plugins, scripts): each function delegates to what the `ros2 topic` verbs use.

`node` is any rclpy node (upstream's NodeStrategy node answers the same graph queries). The
completers take argcomplete's `parsed_args`; they ask the daemon unless `--no-daemon` was given.
"""

from __future__ import annotations

import argparse
import copy
import time
from typing import Any

from ros2cli_lite.command.topic.api import positive_float, positive_int, topics
from ros2cli_lite.qos import add_qos_arguments, configure_profile

__all__ = [
    'TopicMessagePrototypeCompleter', 'TopicNameCompleter', 'TopicTypeCompleter',
    'add_qos_arguments', 'get_msg_class', 'get_topic_names', 'get_topic_names_and_types',
    'message_type_completer', 'positive_float', 'positive_int', 'profile_configure_short_keys',
    'qos_profile_from_short_keys',
]


def get_topic_names_and_types(*, node: Any, include_hidden_topics: bool = False
                              ) -> list[tuple[str, list[str]]]:
    return topics(node, include_hidden_topics)


def get_topic_names(*, node: Any, include_hidden_topics: bool = False) -> list[str]:
    return [name for name, _ in topics(node, include_hidden_topics)]


def get_msg_class(node: Any, topic: str, blocking: bool = False,
                  include_hidden_topics: bool = False) -> Any:
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
        raise RuntimeError(f"Cannot echo topic '{topic}', as it contains more than one type: "
                           f"[{', '.join(found)}]")
    try:
        return get_message(found[0])
    except (AttributeError, ModuleNotFoundError, ValueError):
        raise RuntimeError(f"The message type '{found[0]}' is invalid") from None


def profile_configure_short_keys(profile: Any = None, reliability: str | None = None,
                                 durability: str | None = None, depth: int | None = None,
                                 history: str | None = None, liveliness: str | None = None,
                                 liveliness_lease_duration_s: float | None = None) -> None:
    """Set the policies given by their short keys on `profile` (in place; a depth of 0 or None
    keeps the profile's, as upstream)."""
    configure_profile(profile, reliability=reliability, durability=durability,
                      depth=depth or None, history=history, liveliness=liveliness,
                      lease_seconds=liveliness_lease_duration_s or None)


def qos_profile_from_short_keys(preset_profile: str, reliability: str | None = None,
                                durability: str | None = None, depth: int | None = None,
                                history: str | None = None, liveliness: str | None = None,
                                liveliness_lease_duration_s: float | None = None) -> Any:
    """The preset named `preset_profile` (e.g. 'sensor_data') with the given policies."""
    from rclpy.qos import QoSPresetProfiles

    # A copy: rclpy's presets are shared objects.
    profile = copy.copy(QoSPresetProfiles.get_from_short_key(preset_profile))
    profile_configure_short_keys(profile, reliability, durability, depth, history, liveliness,
                                 liveliness_lease_duration_s)
    return profile


def _graph_topics(parsed_args: argparse.Namespace, include_hidden: bool
                  ) -> list[tuple[str, list[str]]]:
    from ros2cli_lite.graph import graph_source

    use_daemon = not getattr(parsed_args, 'no_daemon', False)
    with graph_source(use_daemon, getattr(parsed_args, 'spin_time', None)) as source:
        return source.graph().topics(include_hidden)


class TopicNameCompleter:
    """Callable returning the topic names (argcomplete completer)."""

    def __init__(self, *, include_hidden_topics_key: str | None = None) -> None:
        self.include_hidden_topics_key = include_hidden_topics_key

    def __call__(self, prefix: str, parsed_args: argparse.Namespace, **kwargs: Any
                 ) -> list[str]:
        hidden = bool(self.include_hidden_topics_key
                      and getattr(parsed_args, self.include_hidden_topics_key, False))
        return [name for name, _ in _graph_topics(parsed_args, hidden)]


def message_type_completer(**kwargs: Any) -> list[str]:
    """Every message type installed, as 'pkg/msg/Name'."""
    from rosidl_runtime_py import get_message_interfaces

    interfaces = get_message_interfaces()
    return [f'{package}/{name}' for package in sorted(interfaces)
            for name in sorted(interfaces[package])]


class TopicTypeCompleter:
    """Callable returning the type of the topic already given, else every message type."""

    def __init__(self, *, topic_name_key: str | None = None) -> None:
        self.topic_name_key = topic_name_key

    def __call__(self, prefix: str, parsed_args: argparse.Namespace, **kwargs: Any
                 ) -> list[str]:
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

    def __call__(self, prefix: str, parsed_args: argparse.Namespace, **kwargs: Any
                 ) -> list[str]:
        from rosidl_runtime_py.utilities import get_message

        from rosidl_runtime_py import message_to_yaml

        message = get_message(getattr(parsed_args, self.topic_type_key))
        return [message_to_yaml(message())]
