"""`ros2 run lifecycle lifecycle_service_client`: lc_client walks lc_talker through
configure, activate, deactivate, activate, deactivate, cleanup and shutdown, one transition
every 10 s, logging each result and the state that follows; it stops at the first failure."""

from __future__ import annotations

import sys
import threading
import time
from typing import Any

from lifecycle_msgs.msg import State, Transition
from lifecycle_msgs.srv import ChangeState, GetState
from node_runtime.spinning import ros_session
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node

LIFECYCLE_NODE = 'lc_talker'
SECONDS_BETWEEN_CHANGES = 10.0
TRANSITION_EVENTS = f'/{LIFECYCLE_NODE}/transition_event'
LISTENER_WAIT = 5.0
SCRIPT = (Transition.TRANSITION_CONFIGURE, Transition.TRANSITION_ACTIVATE,
          Transition.TRANSITION_DEACTIVATE, Transition.TRANSITION_ACTIVATE,
          Transition.TRANSITION_DEACTIVATE, Transition.TRANSITION_CLEANUP,
          Transition.TRANSITION_UNCONFIGURED_SHUTDOWN)


class LifecycleServiceClient(Node):
    def __init__(self, stop: threading.Event) -> None:
        super().__init__('lc_client')
        self._stop = stop
        self._executor = SingleThreadedExecutor()
        self._executor.add_node(self)
        self._get_state = self.create_client(GetState, f'{LIFECYCLE_NODE}/get_state')
        self._change_state = self.create_client(ChangeState, f'{LIFECYCLE_NODE}/change_state')

    def _call(self, client: Any, request: Any, timeout: float) -> Any | None:
        """The response, or None (logged) when the service is missing or does not answer."""
        if not client.wait_for_service(timeout_sec=timeout):
            self.get_logger().error(f'Service {client.srv_name} is not available.')
            return None
        future = client.call_async(request)
        deadline = time.monotonic() + timeout
        while not future.done() and time.monotonic() < deadline and not self._stop.is_set():
            self._executor.spin_once(timeout_sec=0.1)
        if not future.done():
            client.remove_pending_request(future)
            self.get_logger().error(
                f'Server time out while getting current state for node {LIFECYCLE_NODE}')
            return None
        return future.result()

    def close(self) -> None:
        self._executor.shutdown(timeout_sec=1.0)
        self.destroy_node()

    def get_state(self, timeout: float = 3.0) -> int:
        response = self._call(self._get_state, GetState.Request(), timeout)
        if response is None:
            return State.PRIMARY_STATE_UNKNOWN
        self.get_logger().info(f'Node {LIFECYCLE_NODE} has current state '
                               f'{response.current_state.label}.')
        return response.current_state.id

    def change_state(self, transition: int, timeout: float = 3.0) -> bool:
        request = ChangeState.Request(transition=Transition(id=transition))
        response = self._call(self._change_state, request, timeout)
        if response is None:
            return False
        if not response.success:
            self.get_logger().warning(f'Failed to trigger transition {transition}')
            return False
        self.get_logger().info(f'Transition {transition} successfully triggered.')
        return True

    def wait_for_listeners(self, timeout: float = LISTENER_WAIT) -> None:
        """Give subscribers of lc_talker's transition events (lc_listener) up to `timeout`
        to be discovered, so that the first transition's event is not sent before they match
        (started together by the demo's launch file, the listener could miss it on a loaded
        machine; without listeners this only delays the first transition)."""
        deadline = time.monotonic() + timeout
        while (self.count_subscribers(TRANSITION_EVENTS) == 0 and time.monotonic() < deadline
               and not self._stop.is_set()):
            self._executor.spin_once(timeout_sec=0.1)

    def run_script(self) -> None:
        self.wait_for_listeners()
        for index, transition in enumerate(SCRIPT):
            if index and self._stop.wait(SECONDS_BETWEEN_CHANGES):
                return
            if not self.change_state(transition) or not self.get_state():
                return


def main() -> int:
    with ros_session() as stop:
        client = LifecycleServiceClient(stop)
        try:
            client.run_script()
        finally:
            client.close()
    return 0


if __name__ == '__main__':
    sys.exit(main())
