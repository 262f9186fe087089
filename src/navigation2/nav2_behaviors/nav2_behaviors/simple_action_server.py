"""nav2_util::SimpleActionServer on rclpy: one goal executing at a time, one pending.

Upstream's semantics, which every Nav2 server that uses it shows its clients:
- goals are refused while the server is inactive ("Action server is inactive. Rejecting the
  goal.");
- a goal that arrives while another executes waits in the pending slot (a goal already
  waiting there is terminated) and `is_preempt_requested()` turns true; the executing code
  decides what preemption means (`accept_pending_goal()` aborts the old goal, or it
  terminates itself and the worker then starts the pending one);
- `execute` runs on a worker thread of its own, so the node's executor stays free for cancel
  requests, TF and the costmap.

rclpy delivers a goal's result when its execute callback returns: each accepted goal's
callback therefore waits (on an executor thread) until the worker has terminated that goal,
then returns the result the worker stored.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.node import Node

SERVER_TIMEOUT = 0.5  # s deactivate waits for the worker before it terminates the goals


class SimpleActionServer:
    """Upstream's SimpleActionServer<ActionT>: `execute()` reads get_current_goal() itself."""

    def __init__(self, node: Node, action_type: Any, name: str, execute: Callable[[], None],
                 result_timeout: float = 900.0, completion: Callable[[], None] | None = None
                 ) -> None:
        self.node = node
        self.action_type = action_type
        self.name = name
        self._execute = execute
        self._completion = completion
        self._lock = threading.RLock()
        self._active = False
        self._stop = False
        self._preempt = False
        self._current: Any = None
        self._pending: Any = None
        self._worker: threading.Thread | None = None
        self._finished: dict[int, tuple[threading.Event, list[Any]]] = {}
        self._server = ActionServer(
            node, action_type, name, execute_callback=self._on_execute,
            goal_callback=self._on_goal, cancel_callback=self._on_cancel,
            handle_accepted_callback=self._on_accepted,
            callback_group=ReentrantCallbackGroup(),
            result_timeout=max(1, int(result_timeout)))

    # --- rclpy's callbacks ---------------------------------------------------------------
    def _on_goal(self, _goal: Any) -> GoalResponse:
        with self._lock:
            if not self._active:
                self.node.get_logger().info('Action server is inactive. Rejecting the goal.')
                return GoalResponse.REJECT
        return GoalResponse.ACCEPT

    def _on_cancel(self, handle: Any) -> CancelResponse:
        with self._lock:
            if not handle.is_active:
                self._warn('Received request for goal cancellation,but the handle is '
                           'inactive, so reject the request')
                return CancelResponse.REJECT
        return CancelResponse.ACCEPT

    def _on_accepted(self, handle: Any) -> None:
        with self._lock:
            self._finished[id(handle)] = (threading.Event(), [])
            handle.execute()  # EXECUTING now; its callback waits for the worker's verdict
            if self._is_active(self._current) or self._running():
                if self._is_active(self._pending):
                    self._terminate_locked('_pending')
                self._pending = handle
                self._preempt = True
            else:
                self._current = handle
                self._worker = threading.Thread(target=self._work, daemon=True,
                                                 name=f'{self.name}_worker')
                self._worker.start()

    def _on_execute(self, handle: Any) -> Any:
        slot = self._finished.get(id(handle))
        if slot is None:  # accepted before a cleanup dropped the bookkeeping
            handle.abort()
            return self.action_type.Result()
        event, result = slot
        event.wait()
        with self._lock:
            self._finished.pop(id(handle), None)
        return result[0] if result else self.action_type.Result()

    # --- the worker ----------------------------------------------------------------------
    def _work(self) -> None:
        while True:
            with self._lock:
                if self._stop or not self._is_active(self._current):
                    break
            try:
                self._execute()
            except Exception as error:  # an execute bug ends its goal, not the server
                self.node.get_logger().error(
                    f'Action server failed while executing action callback: "{error}"')
                self.terminate_all()
                self._completed()
                return
            with self._lock:
                if self._stop:
                    self._warn('Stopping the thread per request.')
                    self.terminate_all()
                    self._completed()
                    break
                if self._is_active(self._current):
                    self._warn('Current goal was not completed successfully.')
                    self._terminate_locked('_current')
                    self._completed()
                if self._is_active(self._pending):
                    self.accept_pending_goal()
                else:
                    break

    def _completed(self) -> None:
        if self._completion is not None:
            self._completion()

    def _running(self) -> bool:
        return self._worker is not None and self._worker.is_alive() and \
            self._worker is not threading.current_thread()

    # --- what the server's code calls ----------------------------------------------------
    def activate(self) -> None:
        with self._lock:
            self._active, self._stop = True, False

    def deactivate(self) -> None:
        with self._lock:
            self._active, self._stop = False, True
            worker = self._worker
        if worker is not None and worker.is_alive() and worker is not threading.current_thread():
            self._warn('Requested to deactivate server but goal is still executing. Should '
                       'check if action server is running before deactivating.')
            worker.join(SERVER_TIMEOUT)
            if worker.is_alive():
                self.terminate_all()
                self._completed()
                self.node.get_logger().error(
                    f'[{self.name}] [ActionServer] Action callback is still running and '
                    'missed deadline to stop')

    def destroy(self) -> None:
        self.deactivate()
        self.terminate_all()
        self._server.destroy()

    def is_server_active(self) -> bool:
        with self._lock:
            return self._active

    def is_running(self) -> bool:
        return self._worker is not None and self._worker.is_alive()

    def is_preempt_requested(self) -> bool:
        with self._lock:
            return self._preempt

    def is_cancel_requested(self) -> bool:
        with self._lock:
            if self._current is None:
                return False
            if self._pending is not None:
                return self._pending.is_cancel_requested
            return self._current.is_cancel_requested

    def get_current_goal(self) -> Any:
        with self._lock:
            if not self._is_active(self._current):
                self.node.get_logger().error(
                    f'[{self.name}] [ActionServer] A goal is not available or has reached a '
                    'final state')
                return None
            return self._current.request

    def accept_pending_goal(self) -> Any:
        """The pending goal becomes the current one; the current one is aborted."""
        with self._lock:
            if not self._is_active(self._pending):
                self.node.get_logger().error(
                    f'[{self.name}] [ActionServer] Attempting to get pending goal when not '
                    'available')
                return None
            if self._is_active(self._current) and self._current is not self._pending:
                self._finish(self._current, 'abort', self.action_type.Result())
            self._current, self._pending = self._pending, None
            self._preempt = False
            return self._current.request

    def terminate_pending_goal(self) -> None:
        with self._lock:
            if self._is_active(self._pending):
                self._terminate_locked('_pending')
            self._preempt = False

    def terminate_all(self, result: Any = None) -> None:
        with self._lock:
            self._terminate_locked('_current', result)
            self._terminate_locked('_pending', result)
            self._preempt = False

    def terminate_current(self, result: Any = None) -> None:
        with self._lock:
            self._terminate_locked('_current', result)

    def succeeded_current(self, result: Any = None) -> None:
        with self._lock:
            if self._is_active(self._current):
                self._finish(self._current, 'succeed', result)
                self._current = None

    def publish_feedback(self, feedback: Any) -> None:
        with self._lock:
            handle = self._current
        if not self._is_active(handle):
            self.node.get_logger().error(
                f'[{self.name}] [ActionServer] Trying to publish feedback when the current '
                'goal handle is not active')
            return
        handle.publish_feedback(feedback)

    # --- helpers -------------------------------------------------------------------------
    @staticmethod
    def _is_active(handle: Any) -> bool:
        return handle is not None and handle.is_active

    def _terminate_locked(self, slot: str, result: Any = None) -> None:
        handle = getattr(self, slot)
        if self._is_active(handle):
            if handle.is_cancel_requested:
                self.node.get_logger().info(
                    f'[{self.name}] [ActionServer] Client requested to cancel the goal. '
                    'Cancelling.')
                self._finish(handle, 'canceled', result)
            else:
                self._warn('Aborting handle.')
                self._finish(handle, 'abort', result)
        setattr(self, slot, None)

    def _finish(self, handle: Any, how: str, result: Any) -> None:
        getattr(handle, how)()
        slot = self._finished.get(id(handle))
        if slot is not None:
            slot[1].append(result if result is not None else self.action_type.Result())
            slot[0].set()

    def _warn(self, text: str) -> None:
        self.node.get_logger().warning(f'[{self.name}] [ActionServer] {text}')
