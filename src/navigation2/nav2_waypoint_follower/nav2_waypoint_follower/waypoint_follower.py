"""`ros2 run nav2_waypoint_follower waypoint_follower`: Nav2's waypoint follower.

The `follow_waypoints` action sends each of its poses in turn to `navigate_to_pose` (the
stamp set to now), runs the waypoint task executor (`waypoint_task_executor_plugin`) at each
one reached, publishes the index it works on as feedback, and lists the waypoints it could
not reach in `missed_waypoints` with navigate_to_pose's error code. With `stop_on_failure`
the first miss ends the goal ABORTED; without it the follower goes on to the next waypoint.
`number_of_loops` repeats the list, `goal_index` starts part-way. A new goal preempts the
running one (it starts at its first waypoint), a cancel cancels the navigation too.
"""

from __future__ import annotations

import enum
import sys
import threading
import time
from typing import Any

from action_msgs.msg import GoalStatus
from nav2_behaviors.simple_action_server import SimpleActionServer
from nav2_msgs.action import FollowWaypoints, NavigateToPose
from nav2_msgs.msg import MissedWaypoint
from nav2_util.lifecycle_node import LifecycleNode
from nav2_util.parameters import declare_checked, warn_unknown_parameters
from node_runtime.spinning import ros_session, spin_until_stopped
from rcl_interfaces.msg import SetParametersResult
from rclpy.action import ActionClient
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.lifecycle import State, TransitionCallbackReturn
from rclpy.parameter import Parameter

from nav2_waypoint_follower.task_executors import NotBuilt, create_task_executor

SERVER_WAIT = 5.0  # s a waypoint waits for navigate_to_pose to appear before it is missed
CANCEL_WAIT = 2.0  # s a cancel waits for navigate_to_pose to confirm


class ActionStatus(enum.IntEnum):
    UNKNOWN = 0
    PROCESSING = 1
    FAILED = 2
    SUCCEEDED = 3


class WaypointFollower(LifecycleNode):
    def __init__(self) -> None:
        super().__init__('waypoint_follower')
        self.get_logger().info('Creating')
        declare_checked(self, 'stop_on_failure', True)
        declare_checked(self, 'loop_rate', 20)
        declare_checked(self, 'action_server_result_timeout', 900.0)
        declare_checked(self, 'global_frame_id', 'map')
        declare_checked(self, 'waypoint_task_executor_plugin', 'wait_at_waypoint')
        declare_checked(self, 'wait_at_waypoint.plugin', 'nav2_waypoint_follower::WaitAtWaypoint')
        self.server: SimpleActionServer | None = None
        self.client: ActionClient | None = None
        self.task_executor: Any = None
        self._lock = threading.Lock()
        self._status = ActionStatus.UNKNOWN
        self._error_code = 0
        self._goal_token = 0  # which navigate_to_pose goal the callbacks belong to
        self._nav_handle: Any = None
        self._checked_parameters = False
        self._parameters_handler: Any = None

    # --- lifecycle -----------------------------------------------------------------------
    def on_configure(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Configuring')
        self.stop_on_failure = self.get_parameter('stop_on_failure').value
        self.loop_rate = self.get_parameter('loop_rate').value
        if self.loop_rate <= 0:
            self.get_logger().error(
                f"Parameter 'loop_rate' must be > 0 Hz, got {self.loop_rate}")
            return TransitionCallbackReturn.FAILURE
        executor_id = self.get_parameter('waypoint_task_executor_plugin').value
        key = f'{executor_id}.plugin'
        kind = self.get_parameter(key).value if self.has_parameter(key) else \
            declare_checked(self, key, Parameter.Type.STRING)
        try:
            if not kind:
                raise NotBuilt(f"Can not get 'plugin' param value for {executor_id}")
            self.task_executor = create_task_executor(kind)
            self.get_logger().info(
                f'Created waypoint_task_executor : {executor_id} of type {kind}')
            self.task_executor.initialize(self, executor_id)
        except NotBuilt as error:
            self.get_logger().fatal(f'Failed to create waypoint_task_executor. Exception: {error}')
            self.task_executor = None
            return TransitionCallbackReturn.FAILURE
        group = ReentrantCallbackGroup()
        self.client = ActionClient(self, NavigateToPose, 'navigate_to_pose', callback_group=group)
        self.server = SimpleActionServer(
            self, FollowWaypoints, 'follow_waypoints', self._on_follow_waypoints,
            result_timeout=self.get_parameter('action_server_result_timeout').value)
        if not self._checked_parameters:
            warn_unknown_parameters(self)
            self._checked_parameters = True
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Activating')
        self.server.activate()
        self._parameters_handler = self.add_on_set_parameters_callback(
            self._on_set_parameters)
        return super().on_activate(state)

    def on_deactivate(self, state: State) -> TransitionCallbackReturn:
        self.server.deactivate()
        if self._parameters_handler is not None:
            self.remove_on_set_parameters_callback(self._parameters_handler)
            self._parameters_handler = None
        return super().on_deactivate(state)

    def _on_set_parameters(self, parameters: list[Parameter]) -> SetParametersResult:
        """Upstream's dynamic parameters: loop_rate and stop_on_failure, while active."""
        for parameter in parameters:
            if parameter.name == 'loop_rate' and parameter.type_ == Parameter.Type.INTEGER:
                if parameter.value <= 0:
                    return SetParametersResult(
                        successful=False,
                        reason=f'loop_rate must be > 0 Hz, got {parameter.value}')
        for parameter in parameters:
            if parameter.name == 'loop_rate' and parameter.type_ == Parameter.Type.INTEGER:
                self.loop_rate = parameter.value
            elif parameter.name == 'stop_on_failure' and \
                    parameter.type_ == Parameter.Type.BOOL:
                self.stop_on_failure = parameter.value
        return SetParametersResult(successful=True)

    def release(self) -> None:
        if self.server is not None:
            self.server.destroy()
        if self.client is not None:
            self.client.destroy()
        self.server = self.client = self.task_executor = None

    # --- navigate_to_pose ----------------------------------------------------------------
    def _send(self, pose: Any) -> None:
        with self._lock:
            self._goal_token += 1
            token = self._goal_token
            self._status, self._error_code, self._nav_handle = \
                ActionStatus.PROCESSING, 0, None
        if not self.client.wait_for_server(timeout_sec=SERVER_WAIT):
            self.get_logger().error(
                'navigate_to_pose action client failed to send goal to server.')
            self._set(token, ActionStatus.FAILED)
            return
        goal = NavigateToPose.Goal(pose=pose)
        goal.pose.header.stamp = self.get_clock().now().to_msg()
        future = self.client.send_goal_async(goal)
        future.add_done_callback(lambda done: self._on_goal_response(token, done))

    def _on_goal_response(self, token: int, future: Any) -> None:
        handle = future.result()
        if handle is None or not handle.accepted:
            self.get_logger().error(
                'navigate_to_pose action client failed to send goal to server.')
            self._set(token, ActionStatus.FAILED)
            return
        with self._lock:
            if token == self._goal_token:
                self._nav_handle = handle
        handle.get_result_async().add_done_callback(
            lambda done: self._on_result(token, done))

    def _on_result(self, token: int, future: Any) -> None:
        wrapped = future.result()
        if wrapped.status == GoalStatus.STATUS_SUCCEEDED:
            self._set(token, ActionStatus.SUCCEEDED)
        elif wrapped.status == GoalStatus.STATUS_ABORTED:
            self._set(token, ActionStatus.FAILED, wrapped.result.error_code)
        elif wrapped.status == GoalStatus.STATUS_CANCELED:
            self._set(token, ActionStatus.FAILED)
        else:
            self.get_logger().error('Received an UNKNOWN result code from navigation action!')
            self._set(token, ActionStatus.UNKNOWN)

    def _set(self, token: int, status: ActionStatus, error_code: int = 0) -> None:
        with self._lock:
            if token != self._goal_token:
                return  # the result of an older goal
            self._status, self._error_code = status, error_code

    def _cancel_navigation(self) -> None:
        with self._lock:
            self._goal_token += 1
            handle, self._nav_handle = self._nav_handle, None
        if handle is None:
            return
        future = handle.cancel_goal_async()
        deadline = time.monotonic() + CANCEL_WAIT
        while not future.done() and time.monotonic() < deadline:
            time.sleep(0.01)

    # --- follow_waypoints ----------------------------------------------------------------
    def _on_follow_waypoints(self) -> None:
        server = self.server
        goal = server.get_current_goal()
        if goal is None or not server.is_server_active():
            return
        poses = list(goal.poses)
        loops, loop = goal.number_of_loops, 0
        result = FollowWaypoints.Result()
        feedback = FollowWaypoints.Feedback()
        self.get_logger().info(f'Received follow waypoint request with {len(poses)} waypoints.')
        if not poses:
            self.get_logger().error(
                'Empty vector of waypoints passed to waypoint following action potentially due '
                'to conversation failure or empty request.')
            server.terminate_current(result)
            return
        index = goal.goal_index
        if index >= len(poses):
            self.get_logger().error(f'goal_index must be below the number of waypoints '
                                    f'({len(poses)}), got {index}')
            server.terminate_current(result)
            return
        period = 1.0 / self.loop_rate
        new_goal = True
        while server.is_server_active():
            if server.is_cancel_requested():
                self._cancel_navigation()
                server.terminate_all()
                return
            if server.is_preempt_requested():
                self.get_logger().info('Preempting the goal pose.')
                goal = server.accept_pending_goal()
                poses = list(goal.poses) if goal is not None else []
                if not poses:
                    self.get_logger().error(
                        'Empty vector of Waypoints passed to waypoint following logic. Nothing '
                        'to execute, returning with failure!')
                    server.terminate_current(result)
                    return
                loops, loop, index, new_goal = goal.number_of_loops, 0, 0, True
                result = FollowWaypoints.Result()
            if new_goal:
                new_goal = False
                self._send(poses[index])
            feedback.current_waypoint = index
            server.publish_feedback(feedback)
            with self._lock:
                status, error_code = self._status, self._error_code
            if status in (ActionStatus.FAILED, ActionStatus.UNKNOWN):
                result.missed_waypoints.append(
                    MissedWaypoint(index=index, goal=poses[index], error_code=error_code))
                if self.stop_on_failure:
                    self.get_logger().warning(
                        f'Failed to process waypoint {index} in waypoint list and stop on '
                        'failure is enabled. Terminating action.')
                    server.terminate_current(result)
                    return
                self.get_logger().info(f'Failed to process waypoint {index}, moving to next.')
            elif status == ActionStatus.SUCCEEDED:
                self.get_logger().info(f'Succeeded processing waypoint {index}, processing '
                                       'waypoint task execution')
                executed = self.task_executor.process_at_waypoint(poses[index], index)
                self.get_logger().info(f"Task execution at waypoint {index} "
                                       f"{'succeeded' if executed else 'failed!'}")
                if not executed:
                    result.missed_waypoints.append(MissedWaypoint(
                        index=index, goal=poses[index],
                        error_code=FollowWaypoints.Result.TASK_EXECUTOR_FAILED))
                    if self.stop_on_failure:
                        self.get_logger().warning(
                            f'Failed to execute task at waypoint {index}  stop on failure is '
                            'enabled. Terminating action.')
                        server.terminate_current(result)
                        return
                self.get_logger().info(
                    f'Handled task execution on waypoint {index}, moving to next.')
            if status != ActionStatus.PROCESSING:
                index += 1
                new_goal = True
                if index >= len(poses):
                    if loop == loops:
                        self.get_logger().info(
                            f'Completed all {len(poses)} waypoints requested.')
                        server.succeeded_current(result)
                        return
                    self.get_logger().info(
                        f'Starting a new loop, current loop count is {loop}')
                    index = 0
                    loop += 1
            time.sleep(period)


def main(args: list[str] | None = None) -> int:
    with ros_session(args) as stop:
        node = WaypointFollower()
        node.stop_event = stop
        spin_until_stopped(node, stop, MultiThreadedExecutor(num_threads=4))
    return 0


if __name__ == '__main__':
    sys.exit(main())
