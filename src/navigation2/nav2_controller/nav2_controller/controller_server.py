"""`ros2 run nav2_controller controller_server`: Nav2's local controller server.

As upstream, the local costmap runs in the same process as its own lifecycle node
(`local_costmap` in namespace `local_costmap`). The action `follow_path` follows a path with
the controller plugin named by `controller_id` at `controller_frequency`, checking progress
and the goal with the named checkers, and publishes `cmd_vel` (Twist, or TwistStamped with
`enable_stamped_cmd_vel`). A newer goal replaces the path of the running one (which ends
ABORTED, as Nav2's SimpleActionServer does); cancel stops the robot and ends CANCELED; a
zero velocity is published whenever a goal ends.
"""

from __future__ import annotations

import math
import sys
import threading
import time
from typing import Any

import numpy as np
from geometry_msgs.msg import Twist, TwistStamped
from nav2_costmap_2d.costmap_2d_ros import Costmap2DROS
from nav2_msgs.action import FollowPath
from nav2_msgs.msg import SpeedLimit
from nav2_util.lifecycle_node import LifecycleNode, run_server
from nav2_util.parameters import declare_checked, warn_unknown_parameters
from nav_msgs.msg import Odometry
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup, ReentrantCallbackGroup
from rclpy.duration import Duration
from rclpy.lifecycle import State, TransitionCallbackReturn
from rclpy.time import Time
from tf2_ros import TransformException

from nav2_controller import exceptions
from nav2_controller.checkers import GOAL_CHECKERS, PROGRESS_CHECKERS
from nav2_controller.geometry import Pose2D, closest_index, compose, path_length, yaw_of
from nav2_controller.plugins import PluginContext, controller_types, load_controller, plugin_key

DEFAULT_TYPES = {'progress_checker': 'nav2_controller::SimpleProgressChecker',
                 'goal_checker': 'nav2_controller::SimpleGoalChecker',
                 'FollowPath': 'dwb_core::DWBLocalPlanner'}


def concat(ids: list[str]) -> str:
    """Upstream's id list in its lines: every id followed by a space."""
    return ''.join(f'{plugin} ' for plugin in ids)


def path_array(path: Any) -> np.ndarray:
    """nav_msgs/Path -> (N, 3) x, y, yaw."""
    return np.array([(p.pose.position.x, p.pose.position.y, yaw_of(p.pose.orientation))
                     for p in path.poses], dtype=np.float64).reshape(-1, 3)


class ControllerServer(LifecycleNode):
    def __init__(self) -> None:
        super().__init__('controller_server')
        self.get_logger().info('Creating controller server')
        self.controller_frequency = declare_checked(self, 'controller_frequency', 20.0)
        declare_checked(self, 'action_server_result_timeout', 10.0)
        self.ids = {
            'progress_checker': declare_checked(self, 'progress_checker_plugins',
                                                ['progress_checker']),
            'goal_checker': declare_checked(self, 'goal_checker_plugins', ['goal_checker']),
            'FollowPath': declare_checked(self, 'controller_plugins', ['FollowPath'])}
        self.types: dict[str, str] = {}
        for kind, ids in self.ids.items():
            for plugin in ids:
                default = DEFAULT_TYPES[kind] if plugin == kind else ''
                self.types[plugin] = declare_checked(self, f'{plugin}.plugin', default)
        self.min_velocity = tuple(declare_checked(self, f'min_{axis}_velocity_threshold', 0.0001)
                                  for axis in ('x', 'y', 'theta'))
        self.speed_limit_topic = declare_checked(self, 'speed_limit_topic', 'speed_limit')
        self.failure_tolerance = declare_checked(self, 'failure_tolerance', 0.0)
        declare_checked(self, 'use_realtime_priority', False)
        self.publish_zero_velocity = declare_checked(self, 'publish_zero_velocity', True)
        self.costmap_update_timeout = declare_checked(self, 'costmap_update_timeout', 0.30)
        self.odom_topic = declare_checked(self, 'odom_topic', 'odom')
        self.stamped = declare_checked(self, 'enable_stamped_cmd_vel', False)
        # upstream: the local costmap is a node of its own in this process
        self.costmap_ros = Costmap2DROS('local_costmap', 'local_costmap')
        self.controllers: dict[str, Any] = {}
        self.goal_checkers: dict[str, Any] = {}
        self.progress_checkers: dict[str, Any] = {}
        self._handles: list[Any] = []
        self._action: ActionServer | None = None
        self._vel_pub = None
        self._vel_active = False  # the lifecycle publisher is on (upstream: is_activated)
        self._twist = (0.0, 0.0, 0.0)
        self._goal_lock = threading.Lock()  # one control loop at a time
        self._latest_goal: Any = None
        self._handover = False  # the loop that ended passed the robot to a newer goal
        self._warned: set[str] = set()
        self._unknown_checked = False

    # --- lifecycle -----------------------------------------------------------------------
    def on_configure(self, state: State) -> TransitionCallbackReturn:
        log = self.get_logger()
        log.info('Configuring controller interface')
        log.info('getting progress checker plugins..')
        log.info('getting goal checker plugins..')
        log.info(f'Controller frequency set to {self.controller_frequency:.4f}Hz')
        if self.costmap_ros.trigger_configure() != TransitionCallbackReturn.SUCCESS:
            log.error('Failed to configure the local costmap')
            return TransitionCallbackReturn.FAILURE
        if not self._create_plugins():
            self.release()
            return TransitionCallbackReturn.FAILURE
        if not self._unknown_checked:
            warn_unknown_parameters(self)
            self._unknown_checked = True
        group = ReentrantCallbackGroup()
        self._handles = [
            self.create_subscription(Odometry, self.odom_topic, self._on_odom, 10,
                                     callback_group=MutuallyExclusiveCallbackGroup()),
            self.create_subscription(SpeedLimit, self.speed_limit_topic, self._on_speed_limit,
                                     10)]
        self._vel_pub = self.create_lifecycle_publisher(
            TwistStamped if self.stamped else Twist, 'cmd_vel', 1)
        self._action = ActionServer(
            self, FollowPath, 'follow_path', self._on_goal,
            goal_callback=self._on_goal_request, handle_accepted_callback=self._on_accepted,
            cancel_callback=lambda _request: CancelResponse.ACCEPT, callback_group=group)
        return TransitionCallbackReturn.SUCCESS

    def _create_plugins(self) -> bool:
        log = self.get_logger()
        now = self._now
        for plugin in self.ids['progress_checker']:
            cls = PROGRESS_CHECKERS.get(plugin_key(self.types[plugin]))
            if cls is None:
                return self._missing('progress_checker', plugin, 'nav2_core::ProgressChecker',
                                     PROGRESS_CHECKERS)
            log.info(f'Created progress_checker : {plugin} of type {self.types[plugin]}')
            self.progress_checkers[plugin] = cls(self._param_getter(plugin), now)
        log.info(f"Controller Server has {concat(self.ids['progress_checker']) or '(none)'} "
                 'progress checkers available.')
        for plugin in self.ids['goal_checker']:
            cls = GOAL_CHECKERS.get(plugin_key(self.types[plugin]))
            if cls is None:
                return self._missing('goal checker', plugin, 'nav2_core::GoalChecker',
                                     GOAL_CHECKERS)
            log.info(f'Created goal checker : {plugin} of type {self.types[plugin]}')
            self.goal_checkers[plugin] = cls(self._param_getter(plugin))
        log.info(f"Controller Server has {concat(self.ids['goal_checker'])} goal checkers "
                 'available.')
        for plugin in self.ids['FollowPath']:
            kind = self.types[plugin]
            cls = load_controller(kind)
            if cls is None:
                return self._missing('controller', plugin, 'nav2_core::Controller',
                                     controller_types())
            log.info(f'Created controller : {plugin} of type {kind}')
            try:
                self.controllers[plugin] = cls(PluginContext(
                    self, plugin, self.costmap_ros, self._param_getter(plugin)))
            except (exceptions.ControllerException, ValueError) as error:
                log.fatal(f'Failed to create controller. Exception: {error}')
                return False
        log.info(f"Controller Server has {concat(self.ids['FollowPath'])} controllers "
                 'available.')
        return True

    def _missing(self, what: str, plugin: str, base: str, available: Any) -> bool:
        """pluginlib's refusal, in one line naming the types this workspace has."""
        self.get_logger().fatal(
            f'Failed to create {what}. Exception: According to the loaded plugin descriptions '
            f"the class {self.types[plugin] or '(empty)'} with base class type {base} does not "
            f"exist. Declared types are {' '.join(sorted(available))}")
        return False

    def _param_getter(self, plugin: str) -> Any:
        def param(key: str, default: Any) -> Any:
            name = f'{plugin}.{key}'
            if self.has_parameter(name):
                return self.get_parameter(name).value
            return declare_checked(self, name, default)
        return param

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Activating')
        if self.costmap_ros.trigger_activate() != TransitionCallbackReturn.SUCCESS:
            return TransitionCallbackReturn.FAILURE
        for controller in self.controllers.values():
            controller.activate()
        result = super().on_activate(state)
        self._vel_active = True
        return result

    def on_deactivate(self, state: State) -> TransitionCallbackReturn:
        for controller in self.controllers.values():
            controller.deactivate()
        self._publish_velocity((0.0, 0.0, 0.0))  # always stop the robot on deactivate
        self._vel_active = False
        result = super().on_deactivate(state)
        self.costmap_ros.trigger_deactivate()
        return result

    def release(self) -> None:
        for controller in self.controllers.values():
            controller.cleanup()
        if self._action is not None:
            self._action.destroy()
        for handle in self._handles:
            self.destroy_subscription(handle)
        if self._vel_pub is not None:
            self.destroy_lifecycle_publisher(self._vel_pub)
        self.controllers, self.goal_checkers, self.progress_checkers = {}, {}, {}
        self._action, self._vel_pub, self._handles = None, None, []
        self.costmap_ros.run_cleanups()

    def destroy_node(self) -> None:
        super().destroy_node()
        self.costmap_ros.destroy_node()

    # --- inputs --------------------------------------------------------------------------
    def _on_odom(self, msg: Odometry) -> None:
        t = msg.twist.twist
        self._twist = (t.linear.x, t.linear.y, t.angular.z)

    def _on_speed_limit(self, msg: SpeedLimit) -> None:
        for controller in self.controllers.values():
            controller.set_speed_limit(msg.speed_limit, msg.percentage)

    def _now(self) -> float:
        return self.get_clock().now().nanoseconds * 1e-9

    def _thresholded_twist(self) -> Pose2D:
        return tuple(0.0 if abs(v) < limit else v
                     for v, limit in zip(self._twist, self.min_velocity, strict=True))

    # --- goals ---------------------------------------------------------------------------
    def _on_goal_request(self, _goal: Any) -> GoalResponse:
        if not self.is_active():
            self.get_logger().warning('Action server is inactive. Rejecting the goal.')
            return GoalResponse.REJECT
        return GoalResponse.ACCEPT

    def _on_accepted(self, handle: Any) -> None:
        self._latest_goal = handle  # the running loop sees it is no longer the latest
        handle.execute()

    def _select(self, kind: str, requested: str, plugins: dict[str, Any], label: str,
                where: str) -> str:
        if requested in plugins:
            return requested
        if not requested and len(plugins) == 1:
            if kind not in self._warned:
                self._warned.add(kind)
                self.get_logger().warning(
                    f'No {label} was specified in {where}. Server will use only plugin loaded '
                    f'{concat(list(plugins))}. This warning will appear once.')
            return next(iter(plugins))
        raise (exceptions.InvalidController if kind == 'FollowPath' else
               exceptions.ControllerException)(f'Failed to find {label} name: {requested}')

    def _take_goal(self, request: Any, continuing: bool) -> None:
        """setPlannerPath: the goal's plugins, path and end pose become the current ones."""
        names = self.ids['FollowPath'], self.ids['goal_checker']
        try:
            controller = self._select('FollowPath', request.controller_id, self.controllers,
                                      'controller', 'action call')
        except exceptions.InvalidController:
            self.get_logger().error(
                f'FollowPath called with controller name {request.controller_id}, which does '
                f'not exist. Available controllers are: {concat(names[0])}.')
            raise
        try:
            checker = self._select('goal_checker', request.goal_checker_id, self.goal_checkers,
                                   'goal checker', "parameter 'current_goal_checker'")
        except exceptions.ControllerException:
            self.get_logger().error(
                f'FollowPath called with goal_checker name {request.goal_checker_id} in '
                "parameter 'current_goal_checker', which does not exist. Available goal "
                f'checkers are: {concat(names[1])}.')
            raise
        progress = ''
        if self.progress_checkers or request.progress_checker_id:
            progress = self._select('progress_checker', request.progress_checker_id,
                                    self.progress_checkers, 'progress checker',
                                    "parameter 'current_progress_checker'")
        if not request.path.poses:
            raise exceptions.InvalidPath('Path is empty.')
        if progress and (not continuing or progress != self._progress):
            self.progress_checkers[progress].reset()
        self._controller, self._goal_checker, self._progress = controller, checker, progress
        self._path = path_array(request.path)
        self._path_frame = request.path.header.frame_id
        self.controllers[controller].set_plan(self._path)
        self.goal_checkers[checker].reset()

    def _on_goal(self, handle: Any) -> FollowPath.Result:
        result = FollowPath.Result()
        with self._goal_lock:
            continuing, self._handover = self._handover, False
            if handle is not self._latest_goal:
                handle.abort()  # a still newer goal came in while this one waited
                self._handover = continuing
                return result
            if not continuing:
                self.get_logger().info('Received a goal, begin computing control effort.')
            try:
                self._take_goal(handle.request, continuing)
                ended = self._control_loop(handle)
            except exceptions.ControllerException as error:
                self.get_logger().error(str(error))
                self._stop()
                result.error_code, result.error_msg = error.error_code, str(error)
                handle.abort()
                return result
            if ended == 'preempted':
                self._handover = True
                handle.abort()
            elif ended == 'canceled':
                handle.canceled()
            elif ended == 'inactive':
                self._stop()
                handle.abort()
            else:
                self._stop()
                handle.succeed()
            return result

    def _control_loop(self, handle: Any) -> str:
        period = 1.0 / self.controller_frequency
        self._last_valid_cmd = self._now()
        next_tick = time.monotonic()
        while True:
            started = time.monotonic()
            if not self.is_active():
                return 'inactive'
            if handle is not self._latest_goal:
                self.get_logger().info('Passing new path to controller.')
                return 'preempted'
            if handle.is_cancel_requested:
                if self.controllers[self._controller].cancel():
                    self.get_logger().info('Cancellation was successful. Stopping the robot.')
                    self._stop()
                    return 'canceled'
                self.get_logger().info('Waiting for the controller to finish cancellation',
                                       throttle_duration_sec=1.0)
            self._wait_for_costmap()
            # one robot pose and one plan transform per cycle (TF lookups cost in Python)
            pose = self.costmap_ros.get_robot_pose()
            to_costmap = self._plan_to_costmap()
            if self._is_goal_reached(pose, to_costmap):
                self.get_logger().info('Reached the goal!')
                return 'succeeded'
            self._compute_and_publish_velocity(handle, pose, to_costmap)
            next_tick += period
            delay = next_tick - time.monotonic()
            if delay > 0:
                time.sleep(delay)
            else:
                self.get_logger().warning(
                    f'Control loop missed its desired rate of {self.controller_frequency:.4f} '
                    f'Hz. Current loop rate is {1.0 / (time.monotonic() - started):.4f} Hz.')
                next_tick = time.monotonic()

    def _wait_for_costmap(self) -> None:
        deadline = time.monotonic() + self.costmap_update_timeout
        while not self.costmap_ros.is_current():
            if time.monotonic() > deadline:
                raise exceptions.ControllerTimedOut('Costmap timed out waiting for update')
            time.sleep(0.01)

    def _plan_to_costmap(self) -> Pose2D:
        """The plan frame's origin in the local costmap's global frame, from the latest TF."""
        target = self.costmap_ros.global_frame
        if self._path_frame in ('', target):
            return (0.0, 0.0, 0.0)
        try:
            t = self.costmap_ros.tf_buffer.lookup_transform(
                target, self._path_frame, Time(), Duration(seconds=0.1))
        except TransformException as error:
            self.get_logger().error(f'Exception in transformPose: {error}')
            raise exceptions.ControllerTFError(
                'Unable to transform robot pose into global plan\'s frame') from None
        tr = t.transform
        return tr.translation.x, tr.translation.y, yaw_of(tr.rotation)

    def _is_goal_reached(self, pose: Pose2D | None, to_costmap: Pose2D) -> bool:
        if pose is None:
            return False
        end = compose(to_costmap, self._path[-1:])[0]
        return self.goal_checkers[self._goal_checker].is_goal_reached(
            pose, tuple(end), self._thresholded_twist())

    def _compute_and_publish_velocity(self, handle: Any, pose: Pose2D | None,
                                      to_costmap: Pose2D) -> None:
        if pose is None:
            raise exceptions.ControllerTFError('Failed to obtain robot pose')
        if self._progress and not self.progress_checkers[self._progress].check(pose):
            raise exceptions.FailedToMakeProgress('Failed to make progress')
        try:
            command = self.controllers[self._controller].compute_velocity_commands(
                pose, self._thresholded_twist(), self.goal_checkers[self._goal_checker],
                to_costmap)
            self._last_valid_cmd = self._now()
        except exceptions.NoValidControl as error:
            if not (self.failure_tolerance > 0 or self.failure_tolerance == -1.0):
                raise
            self.get_logger().warning(str(error))
            command = (0.0, 0.0, 0.0)
            if self.failure_tolerance != -1.0 and \
                    self._now() - self._last_valid_cmd > self.failure_tolerance:
                raise exceptions.PatienceExceeded('Controller patience exceeded') from None
        feedback = FollowPath.Feedback()
        feedback.speed = math.hypot(command[0], command[1])
        path = compose(to_costmap, self._path)
        feedback.distance_to_goal = path_length(path, closest_index(path, pose[0], pose[1]))
        handle.publish_feedback(feedback)
        self._publish_velocity(command)

    def _publish_velocity(self, command: Pose2D) -> None:
        pub = self._vel_pub
        if pub is None or not self._vel_active or pub.get_subscription_count() == 0:
            return
        twist = Twist()
        twist.linear.x, twist.linear.y, twist.angular.z = (float(v) for v in command)
        if self.stamped:
            msg = TwistStamped()
            msg.header.stamp = self.get_clock().now().to_msg()
            msg.header.frame_id = self.costmap_ros.config.settings['robot_base_frame']
            msg.twist = twist
            pub.publish(msg)
        else:
            pub.publish(twist)

    def _stop(self) -> None:
        """publishZeroVelocity: stop the robot and reset the controllers for the next task."""
        if self.publish_zero_velocity:
            self._publish_velocity((0.0, 0.0, 0.0))
        for controller in self.controllers.values():
            controller.reset()


def main(args: list[str] | None = None) -> int:
    # the local costmap spins beside the server: the control loop waits for its updates
    return run_server(ControllerServer, args, companions=lambda node: [node.costmap_ros])


if __name__ == '__main__':
    sys.exit(main())
