"""The talker and listener every QoS demo runs (in one process, one executor), and how the
demos run them: rclpy.init with clean Ctrl-C, then spin until stopped."""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Callable
from typing import Any

import rclpy
from node_runtime.spinning import SIGNAL_CHECK_PERIOD, ros_session
from rclpy.executors import SingleThreadedExecutor
from rclpy.logging import get_logger
from rclpy.node import Node
from rclpy.qos_overriding_options import InvalidQosOverridesError
from rclpy.timer import Timer
from std_msgs.msg import String


class Talker(Node):
    """Publishes 'Talker says N' every 0.5 s (up to publish_count messages, 0: forever)."""

    def __init__(self, topic: str, qos: Any, event_callbacks: Any, publish_count: int = 0,
                 assert_topic_period: float | None = None) -> None:
        super().__init__('talker')
        self.get_logger().info('Talker starting up')
        self.publisher = self.create_publisher(String, topic, qos,
                                               event_callbacks=event_callbacks)
        self.publish_timer = self.create_timer(0.5, self.publish)
        self.assert_topic_timer: Timer | None = None
        if assert_topic_period:
            self.assert_topic_timer = self.create_timer(assert_topic_period,
                                                        self.publisher.assert_liveliness)
        self.pause_timer: Timer | None = None
        self.publish_count = 0
        self.stop_at_count = publish_count

    def pause_for(self, seconds: float) -> None:
        """Stop publishing for `seconds`, then publish at once and resume (once at a time)."""
        if self.pause_timer is not None:
            return
        self.publish_timer.cancel()
        self.pause_timer = self.create_timer(seconds, self._pause_expired)

    def _pause_expired(self) -> None:
        self.publish()
        self.publish_timer.reset()
        self.destroy_timer(self.pause_timer)
        self.pause_timer = None

    def publish(self) -> None:
        message = String(data=f'Talker says {self.publish_count}')
        self.get_logger().info(f"Publishing: '{message.data}'")
        self.publish_count += 1
        if 0 < self.stop_at_count <= self.publish_count:
            self.publish_timer.cancel()
        self.publisher.publish(message)

    def stop(self) -> None:
        """No more messages nor manual liveliness assertions."""
        if self.assert_topic_timer is not None:
            self.assert_topic_timer.cancel()
            self.assert_topic_timer = None
        self.publish_timer.cancel()


class Listener(Node):
    """Logs what it hears; with defer_subscribe, subscribes only at start_listening()."""

    def __init__(self, topic: str, qos: Any, event_callbacks: Any,
                 defer_subscribe: bool = False) -> None:
        super().__init__('listener')
        self.subscription: Any = None
        self.topic, self.qos, self.event_callbacks = topic, qos, event_callbacks
        if not defer_subscribe:
            self.start_listening()

    def start_listening(self) -> None:
        if self.subscription is None:
            self.subscription = self.create_subscription(
                String, self.topic, self._message_callback, self.qos,
                event_callbacks=self.event_callbacks)
            self.get_logger().info('Listener starting up')

    def _message_callback(self, message: String) -> None:
        self.get_logger().info(f'Listener heard: [{message.data}]')


def positive_int(text: str) -> int:
    """argparse type of the demos' durations (milliseconds) and counts."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f'invalid int value: {text!r}') from None
    if value <= 0:
        raise argparse.ArgumentTypeError(f'must be a positive integer, got {value}')
    return value


def run(make_nodes: Callable[[SingleThreadedExecutor], list[Node]],
        done: Callable[[], bool] = lambda: False) -> int:
    """rclpy.init, the demo's nodes on one executor, spun until Ctrl-C or `done()`. Nodes
    may be removed from the executor and destroyed early; the rest are destroyed at the end."""
    with ros_session() as stop:
        executor = SingleThreadedExecutor()
        try:
            nodes = make_nodes(executor)
        except InvalidQosOverridesError as error:  # a -p qos_overrides... value refused
            get_logger(os.path.basename(sys.argv[0])).error(str(error))
            return 1
        for node in nodes:
            executor.add_node(node)
        try:
            while not stop.is_set() and rclpy.ok() and not done():
                executor.spin_once(timeout_sec=SIGNAL_CHECK_PERIOD)
        finally:
            alive = executor.get_nodes()
            executor.shutdown(timeout_sec=1.0)
            for node in nodes:
                if node in alive:
                    node.destroy_node()
    return 0
