"""BtActionServer: one navigation action served by running a behavior tree (upstream's
nav2_behavior_tree::BtActionServer with nav2_util's SimpleActionServer semantics).

A goal's execute callback only waits for its outcome; the tree runs on the navigator's own
thread, ticking every bt_loop_duration. A newer goal is pending until the next loop, where
the navigator takes it over (the running goal ends ABORTED, the tree goes on with the new
goal on its blackboard); a cancel halts the tree (which cancels the running action) and ends
CANCELED; a failed tree ends ABORTED with the highest-priority error code of
`error_code_names` and the failing node's message.
"""

from __future__ import annotations

import os
import threading
from collections.abc import Callable
from typing import Any

import rclpy
from nav2_behavior_tree.behavior_tree_engine import BehaviorTreeEngine, BtStatus
from nav2_behavior_tree.core import Blackboard
from nav2_behavior_tree.ros_topic_logger import RosTopicLogger
from nav2_behavior_tree.xml_parser import Tree
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.node import Node

OUTCOME_POLL = 0.1  # s: how often a waiting execute callback checks that rclpy still runs


class Outcome:
    """How a goal ended, handed from the tree's thread to the goal's execute callback."""

    def __init__(self) -> None:
        self.done = threading.Event()
        self.status = BtStatus.FAILED
        self.result: Any = None


class BtActionServer:
    def __init__(self, node: Node, action_type: Any, action_name: str, settings: dict[str, Any],
                 blackboard_values: dict[str, Any], default_bt: str,
                 on_goal_received: Callable[[Any], bool], on_loop: Callable[[], None],
                 on_preempt: Callable[[Any], None], may_accept: Callable[[], bool]) -> None:
        self.node = node
        self.logger = node.get_logger()
        self.action_type = action_type
        self.action_name = action_name
        self.settings = settings
        self.default_bt = default_bt
        self.on_goal_received = on_goal_received
        self.on_loop = on_loop
        self.on_preempt = on_preempt
        self.may_accept = may_accept
        self.engine = BehaviorTreeEngine(log=self.logger.error)
        self.blackboard = Blackboard()
        for key, value in blackboard_values.items():
            self.blackboard.set(key, value)
        self.tree: Tree | None = None
        self.topic_logger: RosTopicLogger | None = None
        self.current_bt = ''
        self.error_msg = ''  # why the last goal could not start (goal_received said no)
        self._lock = threading.Lock()
        self._wake = threading.Condition(self._lock)
        self.current: Any = None
        self.pending: Any = None
        self._outcomes: dict[int, Outcome] = {}
        self._active = False
        self._thread: threading.Thread | None = None
        self.server = ActionServer(
            node, action_type, action_name, self._on_execute,
            goal_callback=self._on_goal, handle_accepted_callback=self._on_accepted,
            cancel_callback=lambda _handle: CancelResponse.ACCEPT,
            callback_group=ReentrantCallbackGroup(),
            result_timeout=int(settings['action_server_result_timeout']))

    # --- lifecycle ---------------------------------------------------------------------
    def activate(self) -> bool:
        if not self.load_behavior_tree(self.default_bt):
            self.logger.error(f'Error loading XML file: {self.default_bt}')
            return False
        self._active = True
        self._thread = threading.Thread(target=self._run, name=self.action_name, daemon=True)
        self._thread.start()
        return True

    def deactivate(self) -> None:
        with self._lock:
            self._active = False
            self._wake.notify_all()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(timeout=5.0)
        self._thread = None

    def cleanup(self) -> None:
        self.deactivate()
        if self.tree is not None:
            self.tree.halt_tree()
        self._close_tree()
        self.server.destroy()

    def _close_tree(self) -> None:
        if self.topic_logger is not None:
            self.topic_logger.close()
        if self.tree is not None:
            self.tree.close()
        self.tree, self.topic_logger, self.current_bt = None, None, ''

    # --- the tree ----------------------------------------------------------------------
    def load_behavior_tree(self, filename: str) -> bool:
        filename = filename or self.default_bt
        if self.tree is not None and filename == self.current_bt and \
                not self.settings['always_reload_bt_xml']:
            return True
        if not os.path.isfile(filename):
            self.error_msg = f"Couldn't open input XML file: {filename}"
            self.logger.error(self.error_msg)
            return False
        self._close_tree()
        try:
            self.tree = self.engine.create_tree_from_file(filename, self.blackboard)
        except Exception as error:  # the XML's or a node's error: the goal fails, not us
            self.error_msg = f'Exception when loading BT: {error}'
            self.logger.error(self.error_msg)
            return False
        self.topic_logger = RosTopicLogger(self.blackboard.get('node'), self.tree)
        self.current_bt = filename
        return True

    # --- goals -------------------------------------------------------------------------
    def _on_goal(self, _request: Any) -> GoalResponse:
        if not self._active:
            self.logger.warning('Action server is inactive. Rejecting the goal.')
            return GoalResponse.REJECT
        if not self.may_accept():
            return GoalResponse.REJECT
        return GoalResponse.ACCEPT

    def _on_accepted(self, handle: Any) -> None:
        with self._lock:
            self._outcomes[id(handle)] = Outcome()
            if self.current is None:
                self.current = handle
            else:
                if self.pending is not None:  # an older pending goal never starts
                    self.logger.info('Preempting the pending goal with the new goal')
                    self._finish(self.pending, BtStatus.FAILED, self.action_type.Result())
                self.pending = handle
            self._wake.notify_all()
        handle.execute()

    def _on_execute(self, handle: Any) -> Any:
        outcome = self._outcomes.get(id(handle))
        while outcome is not None and not outcome.done.wait(OUTCOME_POLL):
            if not rclpy.ok():
                break
        with self._lock:
            self._outcomes.pop(id(handle), None)
        if outcome is None or not outcome.done.is_set():
            handle.abort()
            return self.action_type.Result()
        if outcome.status == BtStatus.SUCCEEDED:
            handle.succeed()
        elif outcome.status == BtStatus.CANCELED and handle.is_cancel_requested:
            handle.canceled()
        else:
            handle.abort()
        return outcome.result

    def _finish(self, handle: Any, status: BtStatus, result: Any) -> None:
        outcome = self._outcomes.get(id(handle))
        if outcome is not None:
            outcome.status, outcome.result = status, result
            outcome.done.set()

    def busy(self) -> bool:
        return self.current is not None

    def accept_pending_goal(self) -> Any:
        """The pending goal becomes the current one; the old current one ends ABORTED."""
        with self._lock:
            old, self.current, self.pending = self.current, self.pending, None
            if old is not None and old is not self.current:
                self._finish(old, BtStatus.FAILED, self.action_type.Result())
            return self.current

    def terminate_pending_goal(self) -> None:
        with self._lock:
            pending, self.pending = self.pending, None
            if pending is not None:
                self._finish(pending, BtStatus.FAILED, self.action_type.Result())

    def is_preempt_requested(self) -> bool:
        return self.pending is not None

    def publish_feedback(self, feedback: Any) -> None:
        handle = self.current
        if handle is not None and handle.is_active:
            handle.publish_feedback(feedback)

    # --- the tree's thread -------------------------------------------------------------
    def _run(self) -> None:
        while True:
            with self._lock:
                while self._active and self.current is None:
                    self._wake.wait(0.5)
                if not self._active:
                    self._abort_all()
                    return
                handle = self.current
            self._execute(handle)

    def _abort_all(self) -> None:
        for handle in (self.current, self.pending):
            if handle is not None:
                self._finish(handle, BtStatus.FAILED, self.action_type.Result())
        self.current = self.pending = None

    def _is_canceling(self) -> bool:
        handle = self.current
        return not self._active or handle is None or handle.is_cancel_requested

    def _loop(self) -> None:
        pending = self.pending
        if pending is not None and pending.is_cancel_requested:
            with self._lock:
                self.pending = None
                self._finish(pending, BtStatus.CANCELED, self.action_type.Result())
        elif pending is not None:
            self.on_preempt(pending.request)
        self.topic_logger.flush()
        self.on_loop()

    def _execute(self, handle: Any) -> None:
        self.error_msg = ''
        if not self.on_goal_received(handle.request):
            result = self.action_type.Result(error_msg=self.error_msg)
            with self._lock:
                self._finish(handle, BtStatus.FAILED, result)
                self.current, self.pending = self.pending, None
            self.clean_error_codes()
            return
        status = self.engine.run(self.tree, self._loop, self._is_canceling,
                                 self.settings['bt_loop_duration'],
                                 keep_running=lambda: self._active and rclpy.ok())
        self.engine.halt_all_actions(self.tree)
        self.topic_logger.flush()
        result = self.action_type.Result()
        self.populate_error_code(result)
        with self._lock:
            current, pending = self.current, self.pending
            self.current = self.pending = None
            if status == BtStatus.CANCELED and pending is not None:
                self._finish(pending, BtStatus.CANCELED, self.action_type.Result())
            elif pending is not None:  # arrived on the last tick: it runs next
                self.current = pending
            self._finish(current, status, result)
        if status == BtStatus.SUCCEEDED:
            self.logger.info('Goal succeeded')
        elif status == BtStatus.FAILED:
            self.logger.error('Goal failed')
        else:
            self.logger.info('Goal canceled')
        self.clean_error_codes()

    def populate_error_code(self, result: Any) -> None:
        best = None
        for name in self.settings['error_code_names']:
            code = self.blackboard.get(name)
            if isinstance(code, int) and code != 0 and (best is None or code < best[0]):
                best = (code, name)
        if best is not None:
            result.error_code = best[0]
            messages = self.blackboard.get('__error_msgs__') or {}
            result.error_msg = messages.get(best[1], '')

    def clean_error_codes(self) -> None:
        for name in self.settings['error_code_names']:
            self.blackboard.set(name, 0)
        self.blackboard.set('__error_msgs__', {})
