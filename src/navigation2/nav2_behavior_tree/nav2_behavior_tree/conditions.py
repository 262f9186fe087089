"""Condition nodes: Nav2's conditions (goal, time, distance, TF, battery, error codes) and
BT.CPP's AlwaysSuccess/AlwaysFailure."""

from __future__ import annotations

import time
from typing import Any

from nav2_behavior_tree import robot
from nav2_behavior_tree.core import (
    ConditionNode,
    InputPort,
    NodeStatus,
    is_active,
    ports,
    to_bool,
    to_float,
)

S, F = NodeStatus.SUCCESS, NodeStatus.FAILURE

# nav2_msgs' result codes the recovery conditions look for (FollowPath, ComputePathToPose,
# ComputePathThroughPoses: UNKNOWN, NO_VALID_PATH, TIMEOUT and the controller's).
CONTROLLER_RECOVERABLE = (100, 104, 105, 106)
PLANNER_RECOVERABLE = (200, 204, 208, 300, 304, 308)


def int_list(text: str) -> list[int]:
    """'100;104' or '[100, 104]' -> [100, 104] (BT.CPP splits vectors on ';')."""
    cleaned = text.strip().strip('[]').replace(',', ';')
    return [int(part) for part in cleaned.split(';') if part.strip()]


class AlwaysSuccess(ConditionNode):
    def tick(self) -> NodeStatus:
        return S


class AlwaysFailure(ConditionNode):
    def tick(self) -> NodeStatus:
        return F


class GoalUpdated(ConditionNode):
    """SUCCESS when `goal` or `goals` changed since the node's first tick."""

    PORTS = ports(goal=InputPort(None), goals=InputPort(None))

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.goal = self.goals = None

    def tick(self) -> NodeStatus:
        goal = self.get_input_or_blackboard('goal')
        goals = self.get_input_or_blackboard('goals')
        if not is_active(self.status):
            self.goal, self.goals = goal, goals
            return F
        if goal != self.goal or goals != self.goals:
            self.goal, self.goals = goal, goals
            return S
        return F


class GlobalUpdatedGoal(GoalUpdated):
    """As GoalUpdated, but remembers across halts: only a really new goal counts."""

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.first_time = True

    def tick(self) -> NodeStatus:
        goal = self.get_input_or_blackboard('goal')
        goals = self.get_input_or_blackboard('goals')
        if self.first_time:
            self.first_time = False
            self.goal, self.goals = goal, goals
            return F
        if goal != self.goal or goals != self.goals:
            self.goal, self.goals = goal, goals
            return S
        return F


class GoalReached(ConditionNode):
    PORTS = ports(goal=InputPort(None, None, 'Destination'),
             global_frame=InputPort(str, None, 'Global frame'),
             robot_base_frame=InputPort(str, None, 'Robot base frame'))

    def tick(self) -> NodeStatus:
        goal = self.get_input_or_blackboard('goal')
        frame = self.get_input('global_frame') or self.blackboard.get('global_frame', 'map')
        pose = robot.current_pose(self.blackboard, frame, self.get_input('robot_base_frame'))
        if goal is None or pose is None:
            return F
        target = robot.transform_pose(self.blackboard, goal, frame)
        tolerance = self.blackboard.get('goal_reached_tol', 0.25)
        return S if target is not None and robot.distance(pose, target) <= tolerance else F


class TransformAvailable(ConditionNode):
    PORTS = ports(child=InputPort(str, ''), parent=InputPort(str, ''))

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.was_found = False

    def tick(self) -> NodeStatus:
        if self.was_found:
            return S
        child, parent = self.get_input('child'), self.get_input('parent')
        if not child or not parent:
            robot_log(self, 'error', f'Child frame ({child}) or parent frame ({parent}) were '
                      'empty.')
            return F
        if robot.lookup(self.blackboard, parent, child) is not None:
            self.was_found = True
            return S
        return F


class InitialPoseReceived(ConditionNode):
    PORTS = ports(initial_pose_received=InputPort(to_bool, None))

    def tick(self) -> NodeStatus:
        value = self.get_input_or_blackboard('initial_pose_received', False)
        return S if value else F


class DistanceTraveled(ConditionNode):
    PORTS = ports(distance=InputPort(to_float, 1.0, 'Distance'),
             global_frame=InputPort(str, None), robot_base_frame=InputPort(str, None))

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.start = None

    def tick(self) -> NodeStatus:
        pose = robot.current_pose(self.blackboard, self.get_input('global_frame'),
                                  self.get_input('robot_base_frame'))
        if not is_active(self.status) or self.start is None:
            self.start = pose
            return F
        if pose is None:
            return F
        if robot.distance(pose, self.start) < self.get_input('distance'):
            return F
        self.start = pose
        return S


class TimeExpired(ConditionNode):
    PORTS = ports(seconds=InputPort(to_float, 1.0, 'Seconds'))

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.start = 0.0

    def tick(self) -> NodeStatus:
        if not is_active(self.status):
            self.start = time.monotonic()
            return F
        if time.monotonic() - self.start < self.get_input('seconds'):
            return F
        self.start = time.monotonic()
        return S


class PathExpiringTimer(TimeExpired):
    PORTS = ports(seconds=InputPort(to_float, 1.0, 'Seconds'), path=InputPort(None))

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.path = None

    def tick(self) -> NodeStatus:
        path = self.get_input('path')
        if not is_active(self.status) or path != self.path:
            self.path = path
            self.start = time.monotonic()
            return F
        return super().tick()


class IsStuck(ConditionNode):
    """SUCCESS when the robot brakes harder than brake_accel_limit (m/s^2), as upstream
    reads a sudden stop from odometry."""

    PORTS = ports(brake_accel_limit=InputPort(to_float, -10.0))

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.last = (time.monotonic(), robot.current_speed(self.blackboard))

    def tick(self) -> NodeStatus:
        now, speed = time.monotonic(), robot.current_speed(self.blackboard)
        then, before = self.last
        self.last = (now, speed)
        accel = (speed - before) / (now - then) if now > then else 0.0
        return S if accel < self.get_input('brake_accel_limit') else F


class IsBatteryLow(ConditionNode):
    """Reads sensor_msgs/BatteryState on battery_topic; FAILURE until a message says low."""

    PORTS = ports(min_battery=InputPort(to_float, 0.0, 'Minimum battery percentage/voltage'),
             battery_topic=InputPort(str, '/battery_status', 'Battery topic'),
             is_voltage=InputPort(to_bool, False, 'Use voltage instead of percentage'))

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.is_low = False
        self.subscription = None
        node = self.blackboard.get('node')
        if node is not None:
            from sensor_msgs.msg import BatteryState
            self.subscription = node.create_subscription(
                BatteryState, self.get_input('battery_topic'), self.on_battery_state, 10)

    def on_battery_state(self, msg: Any) -> None:
        level = msg.voltage if self.get_input('is_voltage') else msg.percentage
        self.is_low = level <= self.get_input('min_battery')

    def tick(self) -> NodeStatus:
        return S if self.is_low else F

    def close(self) -> None:
        node = self.blackboard.get('node')
        if node is not None and self.subscription is not None:
            node.destroy_subscription(self.subscription)
            self.subscription = None


class AreErrorCodesPresent(ConditionNode):
    PORTS = ports(error_code=InputPort(int, 0, 'The active error codes'),
             error_codes_to_check=InputPort(int_list, [], 'Error codes to check'))
    CODES: tuple[int, ...] = ()

    def tick(self) -> NodeStatus:
        code = self.get_input('error_code')
        codes = self.CODES or tuple(self.get_input('error_codes_to_check'))
        return S if code in codes else F


class WouldAControllerRecoveryHelp(AreErrorCodesPresent):
    PORTS = ports(error_code=InputPort(int, 0, 'The active error codes'))
    CODES = CONTROLLER_RECOVERABLE


class WouldAPlannerRecoveryHelp(AreErrorCodesPresent):
    PORTS = ports(error_code=InputPort(int, 0, 'The active error codes'))
    CODES = PLANNER_RECOVERABLE


def robot_log(node: Any, level: str, line: str) -> None:
    ros_node = node.blackboard.get('node')
    if ros_node is not None:
        getattr(ros_node.get_logger(), level)(line)


CONDITION_NODES = {cls.__name__: cls for cls in (
    AlwaysSuccess, AlwaysFailure, GoalUpdated, GlobalUpdatedGoal, GoalReached,
    TransformAvailable, InitialPoseReceived, DistanceTraveled, TimeExpired, PathExpiringTimer,
    IsStuck, IsBatteryLow, AreErrorCodesPresent, WouldAControllerRecoveryHelp,
    WouldAPlannerRecoveryHelp)}
