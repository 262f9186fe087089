"""What the AddTwoInts clients share: wait for the service as upstream does (a line a
second), or give up on Ctrl-C."""
from __future__ import annotations

import threading
from collections.abc import Callable

import rclpy
from node_runtime.spinning import SIGNAL_CHECK_PERIOD
from rclpy.client import Client
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.task import Future


def wait_for_service(client: Client, stop: threading.Event,
                     say: Callable[[str], None] = print) -> bool:
    """True once the service is there; False if a Ctrl-C came first."""
    while not client.wait_for_service(timeout_sec=1.0):
        if stop.is_set():
            return False
        say('service not available, waiting again...')
    return not stop.is_set()


def spin_until_done(node: Node, future: Future, stop: threading.Event) -> bool:
    """Spin `node` until `future` is done (True) or a Ctrl-C or shutdown came (False)."""
    return spin_until(node, future.done, stop)


def spin_until(node: Node, done: Callable[[], bool], stop: threading.Event) -> bool:
    """Spin `node` until `done()` (True) or a Ctrl-C or shutdown came (False). A future's done
    callbacks run as executor tasks after the future is done: wait for what they do."""
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    try:
        while not done() and not stop.is_set() and rclpy.ok():
            executor.spin_once(timeout_sec=SIGNAL_CHECK_PERIOD)
    finally:
        executor.remove_node(node)
        executor.shutdown(timeout_sec=1.0)
    return done()
