"""nav2_util::LifecycleServiceClient: drive another node's lifecycle through its services.

Calls block the calling thread until the answer comes, so they must run on an executor
thread other than the one serving the clients' callback group (the lifecycle manager spins
a MultiThreadedExecutor and gives the clients a reentrant group).
"""

from __future__ import annotations

import threading
import time
from typing import Any

import rclpy
from lifecycle_msgs.srv import ChangeState, GetState
from rclpy.callback_groups import CallbackGroup
from rclpy.client import Client
from rclpy.node import Node

WAIT_LOG_PERIOD = 2.0  # seconds between "Waiting for service" lines, as upstream
POLL = 0.1  # seconds: how often a wait checks that the process is still running


class ServiceUnavailable(RuntimeError):
    pass


def call(client: Client, request: Any, timeout: float | None) -> Any | None:
    """The response, or None when none came within `timeout` (None: while rclpy runs)."""
    done = threading.Event()
    future = client.call_async(request)
    future.add_done_callback(lambda _future: done.set())
    deadline = None if timeout is None else time.monotonic() + timeout
    while not done.wait(POLL):
        if not rclpy.ok() or (deadline is not None and time.monotonic() >= deadline):
            client.remove_pending_request(future)
            return None
    return future.result()


class LifecycleServiceClient:
    def __init__(self, node: Node, lifecycle_node_name: str,
                 callback_group: CallbackGroup | None = None,
                 stop: threading.Event | None = None) -> None:
        self._change_state = node.create_client(
            ChangeState, f'{lifecycle_node_name}/change_state', callback_group=callback_group)
        self._get_state = node.create_client(
            GetState, f'{lifecycle_node_name}/get_state', callback_group=callback_group)
        # Block until the server is up, saying so every 2 s (upstream waits forever too;
        # here a stop request or the end of rclpy ends the wait within POLL).
        name = node.resolve_service_name(self._get_state.srv_name)
        next_log = time.monotonic() + WAIT_LOG_PERIOD
        while not self._get_state.wait_for_service(POLL):
            if not rclpy.ok() or (stop is not None and stop.is_set()):
                raise ServiceUnavailable(f'{name} never came up')
            if time.monotonic() >= next_log:
                node.get_logger().info(f'Waiting for service {name}...')
                next_log += WAIT_LOG_PERIOD

    def change_state(self, transition: int, timeout: float = 5.0) -> bool:
        """True when the node accepted and completed the transition."""
        if not self._change_state.wait_for_service(timeout):
            raise ServiceUnavailable('change_state service is not available!')
        request = ChangeState.Request()
        request.transition.id = transition
        response = call(self._change_state, request, None)  # a transition may take long
        return bool(response is not None and response.success)

    def get_state(self, timeout: float = 2.0) -> int:
        if not self._get_state.wait_for_service(timeout):
            raise ServiceUnavailable('get_state service is not available!')
        response = call(self._get_state, GetState.Request(), timeout)
        if response is None:
            raise ServiceUnavailable('get_state service did not answer')
        return response.current_state.id
