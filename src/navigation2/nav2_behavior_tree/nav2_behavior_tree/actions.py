"""Nav2's action leaves that call servers: planning, following, smoothing, the behaviours,
navigation itself and the costmap clearing services, with upstream's ports and defaults."""

from __future__ import annotations

import math
from typing import Any

from builtin_interfaces.msg import Duration
from nav2_msgs import action, srv
from nav_msgs.msg import Path

from nav2_behavior_tree.bt_action_node import (
    ERROR_PORTS,
    BtActionNode,
    BtServiceNode,
    basic_ports,
    service_ports,
)
from nav2_behavior_tree.core import InputPort, NodeStatus, OutputPort, to_bool, to_float


def duration(seconds: float) -> Duration:
    whole = math.floor(seconds)
    return Duration(sec=whole, nanosec=round((seconds - whole) * 1e9) % 1_000_000_000)


def increment_recovery_count(node: BtActionNode) -> None:
    board = node.blackboard
    board.set('number_recoveries', int(board.get('number_recoveries', 0)) + 1)


class ComputePathToPose(BtActionNode):
    ACTION = action.ComputePathToPose
    DEFAULT_NAME = 'compute_path_to_pose'
    PORTS = basic_ports(
        goal=InputPort(None, None, 'Destination to plan to'),
        start=InputPort(None, None, 'Start pose of the path if overriding current robot pose'),
        use_start=InputPort(to_bool, None, 'For using or not using the provided start pose'),
        planner_id=InputPort(str, '', 'Mapped name to the planner plugin type to use'),
        path=OutputPort('Path created by ComputePathToPose node'), **ERROR_PORTS)

    def on_tick(self) -> None:
        goal = self.get_input('goal')
        if goal is not None:
            self.goal.goal = goal
        self.goal.planner_id = self.get_input('planner_id') or ''
        start = self.get_input('start')
        use_start = self.get_input('use_start')
        if use_start is None:
            use_start = start is not None
        elif use_start and start is None:
            self.log().error('use_start is set to true but no start pose was provided, falling '
                             'back to default behavior, i.e. using the current robot pose')
            use_start = False
        self.goal.use_start = bool(use_start)
        if start is not None:
            self.goal.start = start

    def on_success(self, result: Any) -> NodeStatus:
        self.set_output('path', result.path)
        return super().on_success(result)

    def on_aborted(self, result: Any) -> NodeStatus:
        self.set_output('path', Path())
        return super().on_aborted(result)

    def on_cancelled(self, result: Any) -> NodeStatus:
        self.set_output('path', Path())
        return super().on_cancelled(result)

    def halt(self) -> None:
        self.set_output('path', Path())
        super().halt()


class ComputePathThroughPoses(ComputePathToPose):
    ACTION = action.ComputePathThroughPoses
    DEFAULT_NAME = 'compute_path_through_poses'
    PORTS = basic_ports(
        goals=InputPort(None, None, 'Destinations to plan through'),
        start=InputPort(None, None, 'Start pose of the path if overriding current robot pose'),
        use_start=InputPort(to_bool, None, 'For using or not using the provided start pose'),
        planner_id=InputPort(str, '', 'Mapped name to the planner plugin type to use'),
        path=OutputPort('Path created by ComputePathThroughPoses node'), **ERROR_PORTS)

    def on_tick(self) -> None:
        self.goal.goals = list(self.get_input('goals') or [])
        self.goal.planner_id = self.get_input('planner_id') or ''
        start = self.get_input('start')
        self.goal.use_start = start is not None
        if start is not None:
            self.goal.start = start


class FollowPath(BtActionNode):
    ACTION = action.FollowPath
    DEFAULT_NAME = 'follow_path'
    PORTS = basic_ports(
        path=InputPort(None, None, 'Path to follow'),
        controller_id=InputPort(str, ''), goal_checker_id=InputPort(str, ''),
        progress_checker_id=InputPort(str, ''), **ERROR_PORTS)

    def on_tick(self) -> None:
        self.goal.path = self.get_input('path') or Path()
        self.goal.controller_id = self.get_input('controller_id') or ''
        self.goal.goal_checker_id = self.get_input('goal_checker_id') or ''
        self.goal.progress_checker_id = self.get_input('progress_checker_id') or ''

    def on_wait_for_result(self, feedback: Any) -> None:
        # a new path (or a newly selected controller/checker) goes to the controller at once
        path = self.get_input('path')
        if path is not None and path.poses and path != self.goal.path:
            self.goal.path = path
            self.goal_updated = True
        for field in ('controller_id', 'goal_checker_id', 'progress_checker_id'):
            value = self.get_input(field) or ''
            if value != getattr(self.goal, field):
                setattr(self.goal, field, value)
                self.goal_updated = True


class SmoothPath(BtActionNode):
    ACTION = action.SmoothPath
    DEFAULT_NAME = 'smooth_path'
    PORTS = basic_ports(
        unsmoothed_path=InputPort(None, None, 'Path to be smoothed'),
        max_smoothing_duration=InputPort(to_float, 3.0, 'Maximum smoothing duration'),
        check_for_collisions=InputPort(to_bool, False, 'Collision check after smoothing'),
        smoother_id=InputPort(str, ''),
        smoothed_path=OutputPort('Path smoothed by SmootherServer node'),
        smoothing_duration=OutputPort('Time taken to smooth path'),
        was_completed=OutputPort('True if smoothing was not interrupted by time limit'),
        **ERROR_PORTS)

    def on_tick(self) -> None:
        self.goal.path = self.get_input('unsmoothed_path') or Path()
        self.goal.smoother_id = self.get_input('smoother_id') or ''
        self.goal.max_smoothing_duration = duration(self.get_input('max_smoothing_duration'))
        self.goal.check_for_collisions = self.get_input('check_for_collisions')

    def on_success(self, result: Any) -> NodeStatus:
        self.set_output('smoothed_path', result.path)
        self.set_output('smoothing_duration', result.smoothing_duration.sec
                        + result.smoothing_duration.nanosec / 1e9)
        self.set_output('was_completed', result.was_completed)
        return super().on_success(result)


class Spin(BtActionNode):
    ACTION = action.Spin
    DEFAULT_NAME = 'spin'
    PORTS = basic_ports(
        spin_dist=InputPort(to_float, 1.57, 'Spin distance'),
        time_allowance=InputPort(to_float, 10.0, 'Allowed time for spinning'),
        is_recovery=InputPort(to_bool, True, 'True if recovery'), **ERROR_PORTS)

    def on_tick(self) -> None:
        self.goal.target_yaw = self.get_input('spin_dist')
        self.goal.time_allowance = duration(self.get_input('time_allowance'))
        if self.get_input('is_recovery'):
            increment_recovery_count(self)


class Wait(BtActionNode):
    ACTION = action.Wait
    DEFAULT_NAME = 'wait'
    PORTS = basic_ports(wait_duration=InputPort(to_float, 1.0, 'Wait time'))

    def on_tick(self) -> None:
        wait = self.get_input('wait_duration')
        if wait <= 0:
            self.log().warning(f'Wait duration is negative or zero ({wait}). Setting to '
                               'positive.')
            wait = -wait
        self.goal.time = duration(wait)
        increment_recovery_count(self)


class BackUp(BtActionNode):
    ACTION = action.BackUp
    DEFAULT_NAME = 'backup'
    PORTS = basic_ports(
        backup_dist=InputPort(to_float, 0.15, 'Distance to backup'),
        backup_speed=InputPort(to_float, 0.025, 'Speed at which to backup'),
        time_allowance=InputPort(to_float, 10.0, 'Allowed time for reversing'), **ERROR_PORTS)
    DIST, SPEED = 'backup_dist', 'backup_speed'

    def on_tick(self) -> None:
        self.goal.target.x = self.get_input(self.DIST)
        self.goal.speed = self.get_input(self.SPEED)
        self.goal.time_allowance = duration(self.get_input('time_allowance'))
        increment_recovery_count(self)


class DriveOnHeading(BackUp):
    ACTION = action.DriveOnHeading
    DEFAULT_NAME = 'drive_on_heading'
    PORTS = basic_ports(
        dist_to_travel=InputPort(to_float, 0.15, 'Distance to travel'),
        speed=InputPort(to_float, 0.025, 'Speed at which to travel'),
        time_allowance=InputPort(to_float, 10.0, 'Allowed time for driving on heading'),
        **ERROR_PORTS)
    DIST, SPEED = 'dist_to_travel', 'speed'


class AssistedTeleop(BtActionNode):
    ACTION = action.AssistedTeleop
    DEFAULT_NAME = 'assisted_teleop'
    PORTS = basic_ports(
        time_allowance=InputPort(to_float, 10.0, 'Allowed time for running assisted teleop'),
        is_recovery=InputPort(to_bool, False, 'If true the recovery count will be incremented'),
        **ERROR_PORTS)

    def on_tick(self) -> None:
        self.goal.time_allowance = duration(self.get_input('time_allowance'))
        if self.get_input('is_recovery'):
            increment_recovery_count(self)


class NavigateToPose(BtActionNode):
    ACTION = action.NavigateToPose
    DEFAULT_NAME = 'navigate_to_pose'
    PORTS = basic_ports(goal=InputPort(None, None, 'Destination to plan to'),
                        behavior_tree=InputPort(str, '', 'Behavior tree to run'),
                        **ERROR_PORTS)

    def on_tick(self) -> None:
        goal = self.get_input('goal')
        if goal is None:
            self.log().error('NavigateToPoseAction: goal not provided')
            self.should_send_goal = False
            return
        self.goal.pose = goal
        self.goal.behavior_tree = self.get_input('behavior_tree') or ''


class NavigateThroughPoses(BtActionNode):
    ACTION = action.NavigateThroughPoses
    DEFAULT_NAME = 'navigate_through_poses'
    PORTS = basic_ports(goals=InputPort(None, None, 'Destinations to plan through'),
                        behavior_tree=InputPort(str, '', 'Behavior tree to run'),
                        **ERROR_PORTS)

    def on_tick(self) -> None:
        goals = self.get_input('goals')
        if not goals:
            self.log().error('NavigateThroughPosesAction: goals not provided')
            self.should_send_goal = False
            return
        self.goal.poses = list(goals)
        self.goal.behavior_tree = self.get_input('behavior_tree') or ''


class ClearEntireCostmap(BtServiceNode):
    SERVICE = srv.ClearEntireCostmap
    PORTS = service_ports()


class ClearCostmapAroundRobot(BtServiceNode):
    SERVICE = srv.ClearCostmapAroundRobot
    PORTS = service_ports(reset_distance=InputPort(to_float, 1.0, 'Distance from the robot '
                                                   'under which obstacles are cleared'))

    def request(self) -> Any:
        return self.SERVICE.Request(reset_distance=self.get_input('reset_distance'))


class ClearCostmapExceptRegion(ClearCostmapAroundRobot):
    SERVICE = srv.ClearCostmapExceptRegion
    PORTS = service_ports(reset_distance=InputPort(to_float, 1.0, 'Distance from the robot '
                                                   'above which obstacles are cleared'))


ACTION_NODES = {cls.__name__: cls for cls in (
    ComputePathToPose, ComputePathThroughPoses, FollowPath, SmoothPath, Spin, Wait, BackUp,
    DriveOnHeading, AssistedTeleop, NavigateToPose, NavigateThroughPoses, ClearEntireCostmap,
    ClearCostmapAroundRobot, ClearCostmapExceptRegion)}
