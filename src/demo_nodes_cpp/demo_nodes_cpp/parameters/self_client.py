"""The parameter demos talk to their own node through a parameter client, as upstream's do
with rclcpp's SyncParametersClient / AsyncParametersClient."""
from __future__ import annotations

import threading

from demo_nodes_py.services.client_wait import spin_until_done
from rclpy.node import Node
from rclpy.parameter_client import AsyncParameterClient
from rclpy.task import Future


def self_client(node: Node, stop: threading.Event) -> AsyncParameterClient | None:
    """A client of the node's own parameter services once they are found; None on Ctrl-C."""
    client = AsyncParameterClient(node, node.get_fully_qualified_name())
    while not client.wait_for_services(timeout_sec=1.0):
        if stop.is_set():
            node.get_logger().error('Interrupted while waiting for the service. Exiting.')
            return None
        node.get_logger().info('service not available, waiting again...')
    return client


def answer(node: Node, future: Future, stop: threading.Event):
    """The response to a request of the client (the node spins to serve and to receive it);
    None after a Ctrl-C."""
    return future.result() if spin_until_done(node, future, stop) else None
