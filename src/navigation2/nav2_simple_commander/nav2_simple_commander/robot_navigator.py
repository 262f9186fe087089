"""BasicNavigator: Nav2's tasks as blocking or polled calls from a plain Python script.

Upstream Jazzy's (1.3.x) public API, log lines and behaviour: each task method waits for
its action server, sends the goal and returns whether it was accepted; the script then
polls isTaskComplete(), getFeedback() and getResult(), or calls cancelTask(). The path
queries (getPath, getPathThroughPoses, smoothPath) block until their result. Everything
spins this node itself, on rclpy's global executor, as upstream does.
"""

from __future__ import annotations

import time
from enum import Enum
from typing import Any

import rclpy
from action_msgs.msg import GoalStatus
from builtin_interfaces.msg import Duration
from geometry_msgs.msg import Point, PoseStamped, PoseWithCovarianceStamped
from lifecycle_msgs.srv import GetState
from nav2_msgs.action import (
    AssistedTeleop,
    BackUp,
    ComputePathThroughPoses,
    ComputePathToPose,
    DockRobot,
    DriveOnHeading,
    FollowGPSWaypoints,
    FollowPath,
    FollowWaypoints,
    NavigateThroughPoses,
    NavigateToPose,
    SmoothPath,
    Spin,
    UndockRobot,
)
from nav2_msgs.srv import ManageLifecycleNodes
from nav_msgs.msg import Path
from rclpy.action import ActionClient
from rclpy.qos import QoSDurabilityPolicy, QoSHistoryPolicy, QoSProfile, QoSReliabilityPolicy

from nav2_simple_commander._navigator_services import NavigatorServices, finite_number

MANAGER_TYPE = 'nav2_msgs/srv/ManageLifecycleNodes'


class TaskResult(Enum):
    UNKNOWN = 0
    SUCCEEDED = 1
    CANCELED = 2
    FAILED = 3


def _duration(name: str, seconds: float) -> Duration:
    """A Duration message from seconds (whole or fractional), refused when negative."""
    if finite_number(name, seconds) < 0:
        raise ValueError(f'{name} must be >= 0 s, got {seconds!r}')
    nanoseconds = round(float(seconds) * 1e9)
    return Duration(sec=nanoseconds // 1_000_000_000, nanosec=nanoseconds % 1_000_000_000)


class BasicNavigator(NavigatorServices):
    """Nav2's navigation, behaviour, path, docking, costmap and lifecycle calls.

    Numeric arguments (distances, speeds, durations) are checked before anything is sent or
    waited for: a bad one raises ValueError naming it, and nothing changes.
    """

    def __init__(self, node_name: str = 'basic_navigator', namespace: str = '') -> None:
        super().__init__(node_name=node_name, namespace=namespace)
        self.initial_pose = PoseStamped()
        self.initial_pose.header.frame_id = 'map'
        self.goal_handle: Any = None
        self.result_future: Any = None
        self.feedback: Any = None
        self.status: int | None = None
        self.initial_pose_received = False
        self._initial_pose_set = False

        self.nav_through_poses_client = ActionClient(
            self, NavigateThroughPoses, 'navigate_through_poses')
        self.nav_to_pose_client = ActionClient(self, NavigateToPose, 'navigate_to_pose')
        self.follow_waypoints_client = ActionClient(self, FollowWaypoints, 'follow_waypoints')
        self.follow_gps_waypoints_client = ActionClient(
            self, FollowGPSWaypoints, 'follow_gps_waypoints')
        self.follow_path_client = ActionClient(self, FollowPath, 'follow_path')
        self.compute_path_to_pose_client = ActionClient(
            self, ComputePathToPose, 'compute_path_to_pose')
        self.compute_path_through_poses_client = ActionClient(
            self, ComputePathThroughPoses, 'compute_path_through_poses')
        self.smoother_client = ActionClient(self, SmoothPath, 'smooth_path')
        self.spin_client = ActionClient(self, Spin, 'spin')
        self.backup_client = ActionClient(self, BackUp, 'backup')
        self.drive_on_heading_client = ActionClient(self, DriveOnHeading, 'drive_on_heading')
        self.assisted_teleop_client = ActionClient(self, AssistedTeleop, 'assisted_teleop')
        self.docking_client = ActionClient(self, DockRobot, 'dock_robot')
        self.undocking_client = ActionClient(self, UndockRobot, 'undock_robot')

        # amcl latches its pose: a late subscriber still hears the last one.
        amcl_pose_qos = QoSProfile(
            durability=QoSDurabilityPolicy.TRANSIENT_LOCAL,
            reliability=QoSReliabilityPolicy.RELIABLE,
            history=QoSHistoryPolicy.KEEP_LAST,
            depth=1)
        self.localization_pose_sub = self.create_subscription(
            PoseWithCovarianceStamped, 'amcl_pose', self._amclPoseCallback, amcl_pose_qos)
        self.initial_pose_pub = self.create_publisher(
            PoseWithCovarianceStamped, 'initialpose', 10)

    def _actionClients(self) -> list[ActionClient]:
        return [self.nav_through_poses_client, self.nav_to_pose_client,
                self.follow_waypoints_client, self.follow_path_client,
                self.compute_path_to_pose_client, self.compute_path_through_poses_client,
                self.smoother_client, self.spin_client, self.backup_client,
                self.drive_on_heading_client, self.assisted_teleop_client,
                self.follow_gps_waypoints_client, self.docking_client,
                self.undocking_client]

    def destroyNode(self) -> None:
        self.destroy_node()

    def destroy_node(self) -> None:
        for client in self._actionClients():
            client.destroy()
        super().destroy_node()

    def setInitialPose(self, initial_pose: PoseStamped) -> None:
        """Set the initial pose to the localization system."""
        self.initial_pose_received = False
        self.initial_pose = initial_pose
        self._initial_pose_set = True
        self._setInitialPose()

    # --- tasks: send, then poll isTaskComplete / getFeedback / getResult ---------------------

    def _waitForActionServer(self, client: ActionClient, name: str,
                             waiting_line: str | None = None, log_wait: Any = None) -> None:
        (log_wait or self.debug)(f"Waiting for '{name}' action server")
        while not client.wait_for_server(timeout_sec=1.0):
            self.info(waiting_line or f"'{name}' action server not available, waiting...")

    def _sendGoal(self, client: ActionClient, goal: Any, rejected_line: str,
                  feedback: bool = True, log_rejected: Any = None) -> bool:
        """Send the goal; on acceptance keep its handle and result future (the running task)."""
        send_goal_future = client.send_goal_async(
            goal, self._feedbackCallback if feedback else None)
        rclpy.spin_until_future_complete(self, send_goal_future)
        self.goal_handle = send_goal_future.result()
        if not self.goal_handle.accepted:
            (log_rejected or self.error)(rejected_line)
            return False
        self.result_future = self.goal_handle.get_result_async()
        return True

    def goThroughPoses(self, poses: list[PoseStamped], behavior_tree: str = '') -> bool:
        """Send a `NavThroughPoses` action request."""
        self._waitForActionServer(self.nav_through_poses_client, 'NavigateThroughPoses')
        goal = NavigateThroughPoses.Goal(poses=poses, behavior_tree=behavior_tree)
        self.info(f'Navigating with {len(goal.poses)} goals....')
        return self._sendGoal(self.nav_through_poses_client, goal,
                              f'Goal with {len(poses)} poses was rejected!')

    def goToPose(self, pose: PoseStamped, behavior_tree: str = '') -> bool:
        """Send a `NavToPose` action request."""
        self._waitForActionServer(self.nav_to_pose_client, 'NavigateToPose')
        goal = NavigateToPose.Goal(pose=pose, behavior_tree=behavior_tree)
        where = f'{pose.pose.position.x} {pose.pose.position.y}'
        self.info(f'Navigating to goal: {where}...')
        return self._sendGoal(self.nav_to_pose_client, goal, f'Goal to {where} was rejected!')

    def followWaypoints(self, poses: list[PoseStamped]) -> bool:
        """Send a `FollowWaypoints` action request."""
        self._waitForActionServer(self.follow_waypoints_client, 'FollowWaypoints')
        goal = FollowWaypoints.Goal(poses=poses)
        self.info(f'Following {len(goal.poses)} goals....')
        return self._sendGoal(self.follow_waypoints_client, goal,
                              f'Following {len(poses)} waypoints request was rejected!')

    def followGpsWaypoints(self, gps_poses: list[Any]) -> bool:
        """Send a `FollowGPSWaypoints` action request."""
        # Upstream names the plain FollowWaypoints server in these lines.
        self._waitForActionServer(self.follow_gps_waypoints_client, 'FollowWaypoints')
        goal = FollowGPSWaypoints.Goal(gps_poses=gps_poses)
        self.info(f'Following {len(goal.gps_poses)} gps goals....')
        return self._sendGoal(self.follow_gps_waypoints_client, goal,
                              f'Following {len(gps_poses)} gps waypoints request was rejected!')

    def spin(self, spin_dist: float = 1.57, time_allowance: float = 10) -> bool:
        goal = Spin.Goal(target_yaw=finite_number('spin_dist', spin_dist),
                         time_allowance=_duration('time_allowance', time_allowance))
        self._waitForActionServer(self.spin_client, 'Spin')
        self.info(f'Spinning to angle {goal.target_yaw}....')
        return self._sendGoal(self.spin_client, goal, 'Spin request was rejected!')

    def backup(self, backup_dist: float = 0.15, backup_speed: float = 0.025,
               time_allowance: float = 10) -> bool:
        goal = BackUp.Goal(target=Point(x=finite_number('backup_dist', backup_dist)),
                           speed=finite_number('backup_speed', backup_speed),
                           time_allowance=_duration('time_allowance', time_allowance))
        self._waitForActionServer(self.backup_client, 'Backup')
        self.info(f'Backing up {goal.target.x} m at {goal.speed} m/s....')
        return self._sendGoal(self.backup_client, goal, 'Backup request was rejected!')

    def driveOnHeading(self, dist: float = 0.15, speed: float = 0.025,
                       time_allowance: float = 10) -> bool:
        goal = DriveOnHeading.Goal(target=Point(x=finite_number('dist', dist)),
                                   speed=finite_number('speed', speed),
                                   time_allowance=_duration('time_allowance', time_allowance))
        self._waitForActionServer(self.drive_on_heading_client, 'DriveOnHeading')
        self.info(f'Drive {goal.target.x} m on heading at {goal.speed} m/s....')
        return self._sendGoal(self.drive_on_heading_client, goal,
                              'Drive On Heading request was rejected!')

    def assistedTeleop(self, time_allowance: float = 30) -> bool:
        goal = AssistedTeleop.Goal(time_allowance=_duration('time_allowance', time_allowance))
        # Upstream's debug line, typo included: scripts' log filters may look for it.
        self.debug("Wainting for 'assisted_teleop' action server")
        while not self.assisted_teleop_client.wait_for_server(timeout_sec=1.0):
            self.info("'assisted_teleop' action server not available, waiting...")
        self.info("Running 'assisted_teleop'....")
        return self._sendGoal(self.assisted_teleop_client, goal,
                              'Assisted Teleop request was rejected!')

    def followPath(self, path: Path, controller_id: str = '',
                   goal_checker_id: str = '') -> bool:
        """Send a `FollowPath` action request."""
        self._waitForActionServer(self.follow_path_client, 'FollowPath')
        goal = FollowPath.Goal(path=path, controller_id=controller_id,
                               goal_checker_id=goal_checker_id)
        self.info('Executing path...')
        return self._sendGoal(self.follow_path_client, goal, 'Follow path was rejected!')

    def dockRobotByPose(self, dock_pose: PoseStamped, dock_type: str,
                        nav_to_dock: bool = True) -> bool:
        """Send a `DockRobot` action request."""
        self._waitForActionServer(self.docking_client, 'DockRobot',
                                  '"DockRobot" action server not available, waiting...',
                                  self.info)
        goal = DockRobot.Goal(use_dock_id=False, dock_pose=dock_pose, dock_type=dock_type,
                              navigate_to_staging_pose=nav_to_dock)
        self.info(f'Docking at pose: {dock_pose}...')
        return self._sendGoal(self.docking_client, goal, 'Docking request was rejected!',
                              log_rejected=self.info)

    def dockRobotByID(self, dock_id: str, nav_to_dock: bool = True) -> bool:
        """Send a `DockRobot` action request."""
        self._waitForActionServer(self.docking_client, 'DockRobot',
                                  '"DockRobot" action server not available, waiting...',
                                  self.info)
        goal = DockRobot.Goal(use_dock_id=True, dock_id=dock_id,
                              navigate_to_staging_pose=nav_to_dock)
        self.info(f'Docking at dock ID: {dock_id}...')
        return self._sendGoal(self.docking_client, goal, 'Docking request was rejected!',
                              log_rejected=self.info)

    def undockRobot(self, dock_type: str = '') -> bool:
        """Send a `UndockRobot` action request."""
        self._waitForActionServer(self.undocking_client, 'UndockRobot',
                                  '"UndockRobot" action server not available, waiting...',
                                  self.info)
        goal = UndockRobot.Goal(dock_type=dock_type)
        self.info(f'Undocking from dock of type: {dock_type}...')
        return self._sendGoal(self.undocking_client, goal, 'Undocking request was rejected!',
                              log_rejected=self.info)

    def cancelTask(self) -> None:
        """Cancel pending task request of any type."""
        self.info('Canceling current task.')
        if self.result_future:
            future = self.goal_handle.cancel_goal_async()
            rclpy.spin_until_future_complete(self, future)

    def isTaskComplete(self) -> bool:
        """Check if the task request of any type is complete yet (waits up to 0.1 s)."""
        if not self.result_future:
            return True  # no task sent yet
        rclpy.spin_until_future_complete(self, self.result_future, timeout_sec=0.10)
        result = self.result_future.result()
        if not result:
            return False  # still running
        self.status = result.status
        if self.status != GoalStatus.STATUS_SUCCEEDED:
            self.debug(f'Task with failed with status code: {self.status}')
            return True
        self.debug('Task succeeded!')
        return True

    def getFeedback(self) -> Any:
        """Get the pending action feedback message."""
        return self.feedback

    def getResult(self) -> TaskResult:
        """Get the pending action result message."""
        return {GoalStatus.STATUS_SUCCEEDED: TaskResult.SUCCEEDED,
                GoalStatus.STATUS_ABORTED: TaskResult.FAILED,
                GoalStatus.STATUS_CANCELED: TaskResult.CANCELED}.get(self.status,
                                                                     TaskResult.UNKNOWN)

    # --- path queries: block until the server's answer ---------------------------------------

    def _runToResult(self, client: ActionClient, name: str, goal: Any, info_line: str,
                     rejected_line: str) -> Any:
        self._waitForActionServer(client, name)
        self.info(info_line)
        if not self._sendGoal(client, goal, rejected_line, feedback=False):
            return None
        rclpy.spin_until_future_complete(self, self.result_future)
        response = self.result_future.result()
        self.status = response.status
        return response.result

    def _pathOf(self, result: Any) -> Path | None:
        if self.status != GoalStatus.STATUS_SUCCEEDED:
            self.warn(f'Getting path failed with status code: {self.status}')
            return None
        return result.path if result else None

    def _getPathImpl(self, start: PoseStamped, goal: PoseStamped, planner_id: str = '',
                     use_start: bool = False) -> Any:
        """Send a `ComputePathToPose` action request; the whole result, not just the path."""
        request = ComputePathToPose.Goal(start=start, goal=goal, planner_id=planner_id,
                                         use_start=use_start)
        return self._runToResult(self.compute_path_to_pose_client, 'ComputePathToPose',
                                 request, 'Getting path...', 'Get path was rejected!')

    def getPath(self, start: PoseStamped, goal: PoseStamped, planner_id: str = '',
                use_start: bool = False) -> Path | None:
        """Send a `ComputePathToPose` action request."""
        return self._pathOf(self._getPathImpl(start, goal, planner_id, use_start))

    def _getPathThroughPosesImpl(self, start: PoseStamped, goals: list[PoseStamped],
                                 planner_id: str = '', use_start: bool = False) -> Any:
        """Send a `ComputePathThroughPoses` action request; the whole result."""
        request = ComputePathThroughPoses.Goal(start=start, goals=goals,
                                               planner_id=planner_id, use_start=use_start)
        return self._runToResult(self.compute_path_through_poses_client,
                                 'ComputePathThroughPoses', request, 'Getting path...',
                                 'Get path was rejected!')

    def getPathThroughPoses(self, start: PoseStamped, goals: list[PoseStamped],
                            planner_id: str = '', use_start: bool = False) -> Path | None:
        """Send a `ComputePathThroughPoses` action request."""
        return self._pathOf(self._getPathThroughPosesImpl(start, goals, planner_id, use_start))

    def _smoothPathImpl(self, path: Path, smoother_id: str = '', max_duration: float = 2.0,
                        check_for_collision: bool = False) -> Any:
        """Send a `SmoothPath` action request; the whole result."""
        request = SmoothPath.Goal(path=path, smoother_id=smoother_id,
                                  max_smoothing_duration=_duration('max_duration', max_duration),
                                  check_for_collisions=check_for_collision)
        return self._runToResult(self.smoother_client, 'SmoothPath', request,
                                 'Smoothing path...', 'Smooth path was rejected!')

    def smoothPath(self, path: Path, smoother_id: str = '', max_duration: float = 2.0,
                   check_for_collision: bool = False) -> Path | None:
        """Send a `SmoothPath` action request."""
        return self._pathOf(
            self._smoothPathImpl(path, smoother_id, max_duration, check_for_collision))

    # --- bring-up ------------------------------------------------------------------------------

    def waitUntilNav2Active(self, navigator: str = 'bt_navigator',
                            localizer: str = 'amcl') -> None:
        """Block until the full navigation system is up and running."""
        if localizer != 'robot_localization':  # robot_localization is no lifecycle node
            self._waitForNodeToActivate(localizer)
        if localizer == 'amcl':
            self._waitForInitialPose()
        self._waitForNodeToActivate(navigator)
        self.info('Nav2 is ready for use!')

    def _managers(self) -> list[str]:
        return [name for name, types in self.get_service_names_and_types()
                if types and types[0] == MANAGER_TYPE]

    def _callManager(self, srv_name: str, command: int, forward_pose: bool) -> None:
        client = self.create_client(ManageLifecycleNodes, srv_name)
        while not client.wait_for_service(timeout_sec=1.0):
            self.info(f'{srv_name} service not available, waiting...')
        future = client.call_async(ManageLifecycleNodes.Request(command=command))
        last_forward = time.monotonic()
        while not future.done():
            rclpy.spin_until_future_complete(self, future, timeout_sec=0.10)
            # Starting up needs the full map->odom->base_link tree: until the manager answers,
            # forward the initial pose the script set, once a second, as amcl waits for one.
            if (forward_pose and not future.done() and self._initial_pose_set
                    and not self.initial_pose_received
                    and time.monotonic() - last_forward >= 1.0):
                self._setInitialPose()
                last_forward = time.monotonic()
        self.destroy_client(client)

    def lifecycleStartup(self) -> None:
        """Startup nav2 lifecycle system."""
        self.info('Starting up lifecycle nodes based on lifecycle_manager.')
        for srv_name in self._managers():
            self.info(f'Starting up {srv_name}')
            self._callManager(srv_name, ManageLifecycleNodes.Request.STARTUP, True)
        self.info('Nav2 is ready for use!')

    def lifecycleShutdown(self) -> None:
        """Shutdown nav2 lifecycle system."""
        self.info('Shutting down lifecycle nodes based on lifecycle_manager.')
        for srv_name in self._managers():
            self.info(f'Shutting down {srv_name}')
            self._callManager(srv_name, ManageLifecycleNodes.Request.SHUTDOWN, False)

    def _waitForNodeToActivate(self, node_name: str) -> None:
        # Waits for the node within the tester namespace to become active
        self.debug(f'Waiting for {node_name} to become active..')
        node_service = f'{node_name}/get_state'
        state_client = self.create_client(GetState, node_service)
        while not state_client.wait_for_service(timeout_sec=1.0):
            self.info(f'{node_service} service not available, waiting...')
        state = 'unknown'
        while True:
            self.debug(f'Getting {node_name} state...')
            future = state_client.call_async(GetState.Request())
            rclpy.spin_until_future_complete(self, future)
            if future.result() is not None:
                state = future.result().current_state.label
                self.debug(f'Result of get_state: {state}')
            if state == 'active':
                break
            time.sleep(2)  # upstream's polling period
        self.destroy_client(state_client)

    def _waitForInitialPose(self) -> None:
        while not self.initial_pose_received:
            self.info('Setting initial pose')
            self._setInitialPose()
            self.info('Waiting for amcl_pose to be received')
            rclpy.spin_once(self, timeout_sec=1.0)

    def _amclPoseCallback(self, msg: PoseWithCovarianceStamped) -> None:
        self.debug('Received amcl pose')
        self.initial_pose_received = True

    def _feedbackCallback(self, msg: Any) -> None:
        self.debug('Received action feedback message')
        self.feedback = msg.feedback

    def _setInitialPose(self) -> None:
        msg = PoseWithCovarianceStamped()
        msg.pose.pose = self.initial_pose.pose
        msg.header.frame_id = self.initial_pose.header.frame_id
        msg.header.stamp = self.initial_pose.header.stamp
        self.info('Publishing Initial Pose')
        self.initial_pose_pub.publish(msg)

