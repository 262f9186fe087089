"""DataRepublisher: republish the messages of one topic on another, transformed.

    republisher = DataRepublisher(node, 'chatter', 'chatter_upper', String,
                                  lambda msg: String(data=msg.data.upper()))

The transform returns the message to publish, or None to drop it. Messages that arrive
before a subscriber of the publish topic has discovered the republisher are counted as
received, not republished: every message counted as republished reached the subscribers.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any


class DataRepublisher:
    def __init__(self, node: Any, listen_topic: str, publish_topic: str, msg_type: Any,
                 transform_fn: Callable[[Any], Any]) -> None:
        self.__node = node
        self.__transform_fn = transform_fn
        self.__num_received = 0
        self.__republished: list[Any] = []
        # The publisher first: while the first message is on its way, its subscribers can
        # discover it, and that message is not lost to discovery.
        self.__publisher = node.create_publisher(msg_type, publish_topic, 10)
        self.__subscription = node.create_subscription(msg_type, listen_topic,
                                                       self.__on_message, 10)

    def shutdown(self) -> None:
        """Stop republishing."""
        self.__node.destroy_subscription(self.__subscription)
        self.__node.destroy_publisher(self.__publisher)

    def get_num_received(self) -> int:
        return self.__num_received

    def get_num_republished(self) -> int:
        """Messages published (fewer than received when the transform dropped some)."""
        return len(self.__republished)

    def get_republished(self) -> list[Any]:
        """The received messages that were republished (before their transform, as
        upstream keeps them)."""
        return self.__republished

    def __on_message(self, msg: Any) -> None:
        self.__num_received += 1
        if self.__publisher.get_subscription_count() == 0:
            # Nobody subscribed (or discovered us) yet: DDS would drop it; not republished.
            return
        transformed = self.__transform_fn(msg)
        if transformed:
            self.__republished.append(msg)
            self.__publisher.publish(transformed)
