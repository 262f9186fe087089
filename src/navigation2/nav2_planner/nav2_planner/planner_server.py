"""`ros2 run nav2_planner planner_server`: Nav2's global planner server, a lifecycle node.

As upstream, the global costmap runs in the same process as its own lifecycle node
(`global_costmap` in namespace `global_costmap`), configured, activated and cleaned up with
planner_server. The actions `compute_path_to_pose` and `compute_path_through_poses` plan
with the plugin named by `planner_id` (the `planner_plugins`; only
nav2_navfn_planner's NavfnPlanner exists here) and publish the path on `plan`. One goal at a
time: a newer goal preempts the running one, which ends ABORTED.
"""

from __future__ import annotations

import math
import sys
import threading
import time
from typing import Any

from nav2_costmap_2d.costmap_2d_ros import Costmap2DROS
from nav2_msgs.action import ComputePathThroughPoses, ComputePathToPose
from nav2_navfn_planner import exceptions
from nav2_navfn_planner.messages import path_msg, pose_from_msg
from nav2_navfn_planner.navfn_planner import NavfnPlanner
from nav2_util.lifecycle_node import LifecycleNode, run_server
from nav2_util.parameters import declare_checked, warn_unknown_parameters
from nav_msgs.msg import Path
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.duration import Duration
from rclpy.lifecycle import State, TransitionCallbackReturn
from rclpy.time import Time
from tf2_ros import TransformException

# The plugin types this workspace has, by upstream's class name.
PLANNER_TYPES = {'nav2_navfn_planner::NavfnPlanner': NavfnPlanner}
PLUGIN_PARAMETERS = {'tolerance': 0.5, 'use_astar': False, 'allow_unknown': True,
                     'use_final_approach_orientation': False}
COSTMAP_WAIT = 10.0  # seconds a goal waits for a first costmap before it is aborted

Pose = tuple[float, float, float]


def plugin_key(plugin_type: str) -> str:
    """'nav2_navfn_planner/NavfnPlanner' (pluginlib's spelling) -> '...::NavfnPlanner'."""
    return plugin_type.replace('/', '::')


class PlannerServer(LifecycleNode):
    def __init__(self) -> None:
        super().__init__('planner_server')
        self.get_logger().info('Creating')
        self.expected_planner_frequency = declare_checked(
            self, 'expected_planner_frequency', 1.0)
        self.planner_ids: list[str] = declare_checked(self, 'planner_plugins', ['GridBased'])
        self.planner_types: dict[str, str] = {}
        self.plugin_params: dict[str, dict[str, Any]] = {}
        for planner in self.planner_ids:
            default = 'nav2_navfn_planner::NavfnPlanner' if planner == 'GridBased' else ''
            self.planner_types[planner] = declare_checked(self, f'{planner}.plugin', default)
            self.plugin_params[planner] = {
                key: declare_checked(self, f'{planner}.{key}', value)
                for key, value in PLUGIN_PARAMETERS.items()}
        warn_unknown_parameters(self)
        # upstream: the global costmap is a node of its own in this process
        self.costmap_ros = Costmap2DROS('global_costmap', 'global_costmap')
        self.planners: dict[str, NavfnPlanner] = {}
        self._actions: list[ActionServer] = []
        self._plan_pub = None
        self._goal_lock = threading.Lock()  # one goal planned at a time
        self._latest_goal: Any = None
        self._warned_no_id = False

    # --- lifecycle -----------------------------------------------------------------------
    def on_configure(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Configuring')
        if self.costmap_ros.trigger_configure() != TransitionCallbackReturn.SUCCESS:
            self.get_logger().error('Failed to configure the global costmap')
            return TransitionCallbackReturn.FAILURE
        for planner in self.planner_ids:
            kind = self.planner_types[planner]
            cls = PLANNER_TYPES.get(plugin_key(kind))
            if cls is None:
                self.get_logger().fatal(
                    f'Failed to create global planner. Exception: Failed to load plugin '
                    f"'{kind}' for {planner}.plugin: the planners available are "
                    f"{', '.join(sorted(PLANNER_TYPES))}")
                self.costmap_ros.trigger_cleanup()
                return TransitionCallbackReturn.FAILURE
            try:
                self.planners[planner] = cls(planner, self.plugin_params[planner])
            except ValueError as error:
                self.get_logger().fatal(f'Failed to create global planner. Exception: {error}')
                self.costmap_ros.trigger_cleanup()
                return TransitionCallbackReturn.FAILURE
            self.get_logger().info(
                f'Created global planner plugin {planner} of type {kind}')
            self.get_logger().info(f'Configuring plugin {planner} of type NavfnPlanner')
        self.get_logger().info(
            f"Planner Server has {' '.join(self.planner_ids)}  planners available.")
        self._plan_pub = self.create_lifecycle_publisher(Path, 'plan', 1)
        group = ReentrantCallbackGroup()
        self._actions = [
            ActionServer(self, ComputePathToPose, 'compute_path_to_pose',
                         lambda handle: self._on_goal(handle, False),
                         goal_callback=self._on_goal_request,
                         handle_accepted_callback=self._on_accepted,
                         cancel_callback=lambda _request: CancelResponse.ACCEPT,
                         callback_group=group),
            ActionServer(self, ComputePathThroughPoses, 'compute_path_through_poses',
                         lambda handle: self._on_goal(handle, True),
                         goal_callback=self._on_goal_request,
                         handle_accepted_callback=self._on_accepted,
                         cancel_callback=lambda _request: CancelResponse.ACCEPT,
                         callback_group=group)]
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Activating')
        if self.costmap_ros.trigger_activate() != TransitionCallbackReturn.SUCCESS:
            return TransitionCallbackReturn.FAILURE
        for planner in self.planner_ids:
            self.get_logger().info(f'Activating plugin {planner} of type NavfnPlanner')
        return super().on_activate(state)

    def on_deactivate(self, state: State) -> TransitionCallbackReturn:
        result = super().on_deactivate(state)
        self.costmap_ros.trigger_deactivate()
        return result

    def release(self) -> None:
        for action in self._actions:
            action.destroy()
        if self._plan_pub is not None:
            self.destroy_lifecycle_publisher(self._plan_pub)
        self._actions, self._plan_pub, self.planners = [], None, {}
        self.costmap_ros.run_cleanups()

    def destroy_node(self) -> None:
        super().destroy_node()
        self.costmap_ros.destroy_node()

    # --- goals ---------------------------------------------------------------------------
    def _on_goal_request(self, _goal: Any) -> GoalResponse:
        if not self.is_active():
            self.get_logger().warning('Action server is inactive. Rejecting the goal.')
            return GoalResponse.REJECT
        return GoalResponse.ACCEPT

    def _on_accepted(self, handle: Any) -> None:
        self._latest_goal = handle  # the running goal sees it is no longer the latest
        handle.execute()

    def _on_goal(self, handle: Any, through_poses: bool) -> Any:
        action = ComputePathThroughPoses if through_poses else ComputePathToPose
        result = action.Result()
        with self._goal_lock:
            if handle is not self._latest_goal:
                self.get_logger().info('Preempting the goal with the new goal')
                handle.abort()
                return result
            if handle.is_cancel_requested:
                handle.canceled()
                return result
            started = time.monotonic()
            try:
                plan = self._plan(handle, handle.request, through_poses)
            except exceptions.PlannerCancelled:
                if handle is not self._latest_goal:
                    self.get_logger().info('Preempting the goal with the new goal')
                    handle.abort()
                    return result
                self.get_logger().info('Goal was canceled. Canceling planning action.')
                handle.canceled()
                return result
            except exceptions.PlannerException as error:
                self._warn_failure(handle.request, through_poses, error)
                result.error_code = error.error_code(through_poses)
                result.error_msg = str(error)
                handle.abort()
                return result
            elapsed = time.monotonic() - started
            result.path = path_msg(plan, self.costmap_ros.global_frame,
                                   self.get_clock().now().to_msg())
            result.planning_time = Duration(seconds=elapsed).to_msg()
            if self.expected_planner_frequency > 0 and \
                    elapsed > 1.0 / self.expected_planner_frequency:
                self.get_logger().warning(
                    f'Planner loop missed its desired rate of '
                    f'{self.expected_planner_frequency:.4f} Hz. Current loop rate is '
                    f'{1.0 / elapsed:.4f} Hz')
            self._plan_pub.publish(result.path)
            handle.succeed()
            return result

    def _warn_failure(self, request: Any, through_poses: bool, error: Exception) -> None:
        goal = request.goals[-1] if through_poses and request.goals else \
            getattr(request, 'goal', None)
        start = request.start.pose.position
        end = goal.pose.position if goal is not None else start
        self.get_logger().warning(
            f'{request.planner_id or self.planner_ids[0]} plugin failed to plan from '
            f'({start.x:.2f}, {start.y:.2f}) to ({end.x:.2f}, {end.y:.2f}): "{error}"')

    def _plan(self, handle: Any, request: Any, through_poses: bool) -> list[Pose]:
        planner = self._planner(request.planner_id)
        self._wait_for_costmap(handle)
        start = self._start(request)
        request.start.pose.position.x, request.start.pose.position.y = start[0], start[1]
        poses = list(request.goals) if through_poses else [request.goal]
        if through_poses and not poses:
            raise exceptions.NoViapointsGiven('No viapoints given')
        goals = [self._to_global(pose, 'goal') for pose in poses]
        goal = goals[-1]
        self.get_logger().info(
            f'Computing path to goal ({goal[0]:.2f}, {goal[1]:.2f}) from '
            f'({start[0]:.2f}, {start[1]:.2f}) with {request.planner_id or self.planner_ids[0]}')

        def cancelled() -> bool:
            return handle.is_cancel_requested or handle is not self._latest_goal

        with self.costmap_ros.lock:
            costmap = self.costmap_ros.costmap
            if through_poses:
                plan = planner.create_plan_through_poses(costmap, start, goals, cancelled)
            else:
                plan = planner.create_plan(costmap, start, goal, cancelled)
        if cancelled():
            raise exceptions.PlannerCancelled('cancelled')
        if not plan:
            raise exceptions.NoValidPathCouldBeFound(
                f'{planner.name} generated a empty path')
        return plan

    def _planner(self, planner_id: str) -> NavfnPlanner:
        if not planner_id and len(self.planners) == 1:
            if not self._warned_no_id:
                self.get_logger().warning(
                    'No planners specified in action call. Server will use only plugin '
                    f'{self.planner_ids[0]} in server. This warning will appear once.')
                self._warned_no_id = True
            return self.planners[self.planner_ids[0]]
        if planner_id in self.planners:
            return self.planners[planner_id]
        self.get_logger().error(
            f"planner {planner_id} is not a valid planner. Planner names are: "
            f"{' '.join(self.planner_ids)}")
        raise exceptions.InvalidPlanner(f'Planner id {planner_id} is invalid')

    def _wait_for_costmap(self, handle: Any) -> None:
        deadline = time.monotonic() + COSTMAP_WAIT
        while not self.costmap_ros.is_current():
            if handle.is_cancel_requested or handle is not self._latest_goal:
                raise exceptions.PlannerCancelled('cancelled')
            if time.monotonic() > deadline:
                raise exceptions.PlannerException(
                    f'The global costmap is not current after {COSTMAP_WAIT:.0f} s (no map '
                    'or no robot pose yet)')
            time.sleep(0.05)

    def _start(self, request: Any) -> Pose:
        if request.use_start:
            return self._to_global(request.start, 'start')
        pose = self.costmap_ros.get_robot_pose()
        if pose is None:
            raise exceptions.PlannerTFError('Could not get robot pose')
        return pose

    def _to_global(self, pose: Any, field: str) -> Pose:
        """A PoseStamped in the costmap's frame (TF for another frame); NaN is refused."""
        x, y, yaw = pose_from_msg(pose)
        if not all(math.isfinite(v) for v in (x, y, yaw)):
            outside = exceptions.GoalOutsideMapBounds if field == 'goal' else \
                exceptions.StartOutsideMapBounds
            raise outside(f'{field} pose is not finite: ({x}, {y}, yaw {yaw})')
        frame = pose.header.frame_id
        global_frame = self.costmap_ros.global_frame
        if frame == global_frame:
            return x, y, yaw
        try:
            t = self.costmap_ros.tf_buffer.lookup_transform(
                global_frame, frame, Time(), Duration(seconds=0.3))
        except (TransformException, TypeError) as error:
            self.get_logger().error(f'Unable to transform {field} pose from frame '
                                    f"'{frame}' into {global_frame}: {error}")
            raise exceptions.PlannerTFError(
                'Unable to transform poses to global frame') from None
        tr = t.transform
        q = tr.rotation
        theta = math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))
        c, s = math.cos(theta), math.sin(theta)
        return (tr.translation.x + c * x - s * y, tr.translation.y + s * x + c * y,
                yaw + theta)


def main(args: list[str] | None = None) -> int:
    return run_server(PlannerServer, args, companions=lambda node: [node.costmap_ros])


if __name__ == '__main__':
    sys.exit(main())
