"""WaitForTopics: wait until at least one message arrived on each of some topics.

    with WaitForTopics([('chatter', String)], timeout=5.0) as wait_for_node:
        print(wait_for_node.received_messages('chatter'))

or `wait = WaitForTopics(...); assert wait.wait(); wait.shutdown()`. The subscriptions live on a
node of their own, in a context of their own, spun on a thread of their own, so a test can
use it while the launch runs.
"""

from __future__ import annotations

import random
import string
import threading
import time
from collections import deque
from typing import Any

import rclpy
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node


class WaitForTopics:
    def __init__(self, topic_tuples: list[tuple[str, Any]], timeout: float = 5.0,
                 messages_received_buffer_length: int = 10,
                 node_namespace: str | None = None) -> None:
        self.topic_tuples = list(topic_tuples)
        self.timeout = timeout
        self.messages_received_buffer_length = messages_received_buffer_length
        self._node_namespace = node_namespace
        self._context = Context()
        rclpy.init(context=self._context)
        suffix = ''.join(random.choices(string.ascii_lowercase, k=10))
        self._node = Node(f'wait_for_topics_{suffix}', namespace=node_namespace or '',
                          context=self._context)
        self._lock = threading.Condition()
        self._messages: dict[str, deque[Any]] = {}
        for topic, message_type in self.topic_tuples:
            self._messages[topic] = deque(maxlen=messages_received_buffer_length)
            self._node.create_subscription(
                message_type, topic, lambda message, name=topic: self._on_message(name, message),
                10)
        self._executor = SingleThreadedExecutor(context=self._context)
        self._executor.add_node(self._node)
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._spin, daemon=True, name='wait_for_topics')
        self._thread.start()

    def _spin(self) -> None:
        while not self._stop.is_set() and self._context.ok():
            self._executor.spin_once(timeout_sec=0.05)

    def _on_message(self, topic: str, message: Any) -> None:
        with self._lock:
            self._messages[topic].append(message)
            self._lock.notify_all()

    def wait(self) -> bool:
        """True once every topic had a message, False after `timeout` seconds."""
        deadline = time.monotonic() + self.timeout
        with self._lock:
            return self._lock.wait_for(lambda: not self.topics_not_received(),
                                       timeout=max(0.0, deadline - time.monotonic()))

    def topics_received(self) -> set[str]:
        return {topic for topic, messages in self._messages.items() if messages}

    def topics_not_received(self) -> set[str]:
        return {topic for topic, messages in self._messages.items() if not messages}

    def received_messages(self, topic_name: str) -> list[Any]:
        if topic_name not in self._messages:
            raise KeyError(f'{topic_name} is not one of the topics waited for: '
                           f"{', '.join(sorted(self._messages))}")
        with self._lock:
            return list(self._messages[topic_name])

    def shutdown(self) -> None:
        self._stop.set()
        self._thread.join(timeout=2.0)
        self._executor.shutdown(timeout_sec=1.0)
        self._node.destroy_node()
        rclpy.try_shutdown(context=self._context)

    def __enter__(self) -> WaitForTopics:
        if not self.wait():
            self.shutdown()
            raise RuntimeError('Did not receive messages on these topics: '
                               f"{', '.join(sorted(self.topics_not_received()))}")
        return self

    def __exit__(self, *_exc: Any) -> None:
        self.shutdown()
