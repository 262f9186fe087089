"""BtActionNode and BtServiceNode: BT leaves that call a Nav2 server without blocking a tick.

The clients live on the node the blackboard holds as `node` (bt_navigator's client node,
spun by a multi-threaded executor): a tick sends the goal or request, then only looks at
its futures. As upstream, the constructor waits up to `wait_for_service_timeout` for the
server (a tree naming a server that is not there does not load), a goal not acknowledged
within `server_timeout` fails the node, and halting a running node cancels its goal.
"""

from __future__ import annotations

import threading
import time
from typing import Any

from action_msgs.msg import GoalStatus
from rclpy.action import ActionClient

from nav2_behavior_tree.core import (
    ActionNode,
    BehaviorTreeException,
    InputPort,
    NodeStatus,
    OutputPort,
    is_active,
)

# rclpy over DDS on a loaded 2-core machine acknowledges a goal in 1-50 ms; upstream's
# default_server_timeout of 20 ms (made for C++) would fail goals at random, so an
# acknowledgement is waited for at least this long (README: how we differ).
MIN_SERVER_TIMEOUT = 1.0
CANCEL_WAIT = 1.0  # s halt() waits for the server to accept a cancel
# Discovery of another process's servers takes rclpy seconds under load where rclcpp takes
# a fraction of one: a server is waited for at least this long when a tree loads (one wait
# per load: the first server missing ends it).
MIN_WAIT_FOR_SERVICE = 5.0


class ThreadSafeActionClient(ActionClient):
    """rclpy's ActionClient registers a request's future only after sending it: a response
    that an executor thread takes in between is dropped ("Ignoring unexpected goal
    response"), seen here when the tree's thread sends goals. One lock orders the two."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        super().__init__(*args, **kwargs)
        self._requests_lock = threading.RLock()

    def send_goal_async(self, *args: Any, **kwargs: Any) -> Any:
        with self._requests_lock:
            return super().send_goal_async(*args, **kwargs)

    def _cancel_goal_async(self, *args: Any, **kwargs: Any) -> Any:
        with self._requests_lock:
            return super()._cancel_goal_async(*args, **kwargs)

    def _get_result_async(self, *args: Any, **kwargs: Any) -> Any:
        with self._requests_lock:
            return super()._get_result_async(*args, **kwargs)

    async def execute(self, taken_data: Any) -> None:
        with self._requests_lock:
            await super().execute(taken_data)


def basic_ports(**ports: Any) -> dict[str, Any]:
    base = {'server_name': InputPort(str, None, 'Action server name'),
            'server_timeout': InputPort(int, None, 'Server timeout (ms)')}
    base.update(ports)
    return base


class _ServerNode(ActionNode):
    """What action and service leaves share: the client node, names and timeouts."""

    DEFAULT_NAME = ''

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.node = self.blackboard.get('node')
        if self.node is None:
            raise BehaviorTreeException(f"{self.registration_name}: no 'node' on the blackboard")
        self.server_name = self.resolve_server_name()
        ms = self.get_input('server_timeout')
        board = self.blackboard.get('server_timeout', 0.02)  # seconds
        self.server_timeout = max(ms / 1000.0 if ms is not None else board, MIN_SERVER_TIMEOUT)
        self.wait_for_service_timeout = max(
            self.blackboard.get('wait_for_service_timeout', 1.0), MIN_WAIT_FOR_SERVICE)
        self.group = self.blackboard.get('callback_group')

    NAME_PORT = 'server_name'

    def resolve_server_name(self) -> str:
        return self.get_input(self.NAME_PORT) or self.DEFAULT_NAME

    def log(self) -> Any:
        return self.node.get_logger()

    def set_error(self, code: int, message: str = '') -> None:
        """error_code_id (and error_msg) out; the navigator reports the failing node's."""
        self.set_output('error_code_id', code)
        self.set_output('error_msg', message)
        text = self.attributes.get('error_code_id', '')
        key = text.strip()[1:-1] if text.strip().startswith('{') else text.strip()
        if key:
            messages = self.blackboard.root().get('__error_msgs__')
            if messages is None:
                messages = {}
                self.blackboard.root().set('__error_msgs__', messages)
            messages[key.lstrip('@')] = message


class BtActionNode(_ServerNode):
    ACTION: Any = None

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.client = ThreadSafeActionClient(self.node, self.ACTION, self.server_name,
                                   callback_group=self.group)
        if not self.client.wait_for_server(timeout_sec=self.wait_for_service_timeout):
            self.log().error(f'"{self.server_name}" action server not available after waiting '
                             f'for {self.wait_for_service_timeout:.2f}s')
            self.client.destroy()
            raise BehaviorTreeException(f'Action server {self.server_name} not available')
        self.goal = self.ACTION.Goal()
        self.should_send_goal = True
        self.goal_updated = False
        self.goal_future = None
        self.goal_handle = None
        self.result_future = None
        self.feedback = None
        self.sent_at = 0.0

    # --- what subclasses override ---------------------------------------------------------
    def on_tick(self) -> None:
        """Fill self.goal from the ports."""

    def on_wait_for_result(self, feedback: Any) -> None:
        """Look at the latest feedback; set goal_updated to send self.goal again."""

    def on_success(self, result: Any) -> NodeStatus:
        self.set_error(0)
        return NodeStatus.SUCCESS

    def on_aborted(self, result: Any) -> NodeStatus:
        self.set_error(getattr(result, 'error_code', 0), getattr(result, 'error_msg', ''))
        return NodeStatus.FAILURE

    def on_cancelled(self, result: Any) -> NodeStatus:
        self.set_error(0)
        return NodeStatus.SUCCESS

    # --- the protocol ---------------------------------------------------------------------
    def send_new_goal(self) -> None:
        self.feedback = None
        self.goal_future = self.client.send_goal_async(self.goal, self.on_feedback)
        self.sent_at = time.monotonic()

    def on_feedback(self, msg: Any) -> None:
        self.feedback = msg.feedback

    def _acknowledged(self) -> NodeStatus | None:
        """None once the goal is accepted; RUNNING while waiting; FAILURE otherwise."""
        if not self.goal_future.done():
            if time.monotonic() - self.sent_at < self.server_timeout:
                return NodeStatus.RUNNING
            self.log().warning('Timed out while waiting for action server to acknowledge goal '
                               f'request for {self.server_name}')
            self.goal_future.add_done_callback(cancel_when_accepted)
            self.goal_future = None
            return NodeStatus.FAILURE
        handle = self.goal_future.result()
        self.goal_future = None
        if handle is None or not handle.accepted:
            return NodeStatus.FAILURE
        self.goal_handle = handle
        self.result_future = handle.get_result_async()
        return None

    def tick(self) -> NodeStatus:
        if not is_active(self.status):
            self.should_send_goal = True
            self.goal = self.ACTION.Goal()
            self.goal_handle = self.result_future = None
            self.on_tick()
            self.status = NodeStatus.RUNNING
            if not self.should_send_goal:
                return NodeStatus.FAILURE
            self.send_new_goal()
        if self.goal_future is not None:
            waiting = self._acknowledged()
            if waiting is not None:
                return waiting
        if not self.result_future.done():
            feedback, self.feedback = self.feedback, None
            self.on_wait_for_result(feedback)
            if self.goal_updated and self.goal_handle.status in (
                    GoalStatus.STATUS_ACCEPTED, GoalStatus.STATUS_EXECUTING):
                self.goal_updated = False
                self.send_new_goal()
                waiting = self._acknowledged()
                if waiting is not None:
                    return waiting
            return NodeStatus.RUNNING
        response = self.result_future.result()
        self.goal_handle = self.result_future = None
        if response.status == GoalStatus.STATUS_SUCCEEDED:
            return self.on_success(response.result)
        if response.status == GoalStatus.STATUS_CANCELED:
            return self.on_cancelled(response.result)
        return self.on_aborted(response.result)

    def halt(self) -> None:
        if self.goal_future is not None:  # sent, not yet acknowledged: cancel on arrival
            self.goal_future.add_done_callback(cancel_when_accepted)
            self.goal_future = None
        handle = self.goal_handle
        if self.status == NodeStatus.RUNNING and handle is not None and handle.status in (
                GoalStatus.STATUS_ACCEPTED, GoalStatus.STATUS_EXECUTING):
            answered = threading.Event()
            handle.cancel_goal_async().add_done_callback(lambda _future: answered.set())
            if not answered.wait(max(self.server_timeout, CANCEL_WAIT)):
                self.log().error(f'Failed to cancel action server for {self.server_name}')
        self.goal_handle = self.result_future = None
        self.reset_status()

    def close(self) -> None:
        self.client.destroy()


def cancel_when_accepted(future: Any) -> None:
    handle = future.result()
    if handle is not None and handle.accepted:
        handle.cancel_goal_async()


class BtServiceNode(_ServerNode):
    """A leaf that calls a service: RUNNING until the answer, FAILURE after server_timeout."""

    SERVICE: Any = None
    NAME_PORT = 'service_name'

    def __init__(self, *args) -> None:
        super().__init__(*args)
        if not self.server_name:
            raise BehaviorTreeException(
                f'{self.registration_name} (line {self.line}): service_name is required')
        self.client = self.node.create_client(self.SERVICE, self.server_name,
                                              callback_group=self.group)
        if not self.client.wait_for_service(timeout_sec=self.wait_for_service_timeout):
            self.log().error(f'"{self.server_name}" service server not available after '
                             f'waiting for {self.wait_for_service_timeout:.2f} s')
            self.node.destroy_client(self.client)
            raise BehaviorTreeException(
                f'Service server {self.server_name} not available')
        self.future = None
        self.sent_at = 0.0

    def request(self) -> Any:
        return self.SERVICE.Request()

    def tick(self) -> NodeStatus:
        if not is_active(self.status) or self.future is None:
            self.future = self.client.call_async(self.request())
            self.sent_at = time.monotonic()
        if self.future.done():
            self.future = None
            return NodeStatus.SUCCESS
        if time.monotonic() - self.sent_at < self.server_timeout:
            return NodeStatus.RUNNING
        self.log().warning(
            f"Node timed out while executing service call to {self.server_name}.")
        self.client.remove_pending_request(self.future)
        self.future = None
        return NodeStatus.FAILURE

    def halt(self) -> None:
        if self.future is not None:
            self.client.remove_pending_request(self.future)
            self.future = None
        self.reset_status()

    def close(self) -> None:
        self.node.destroy_client(self.client)


def service_ports(**ports: Any) -> dict[str, Any]:
    base = {'service_name': InputPort(str, None, 'Service name'),
            'server_timeout': InputPort(int, None, 'Server timeout (ms)')}
    base.update(ports)
    return base


ERROR_PORTS = {'error_code_id': OutputPort('The error code'),
               'error_msg': OutputPort('The error message')}
