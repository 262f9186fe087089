"""nav2_controller's goal and progress checker plugins, as plain classes.

Each takes its parameters through `param(name, default)` (the server declares
`<plugin>.<name>` on itself, as upstream's declare_parameter_if_not_declared does).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

from nav2_controller.geometry import Pose2D, shortest_angular_distance

ParamGetter = Callable[[str, Any], Any]


class SimpleGoalChecker:
    """nav2_controller::SimpleGoalChecker: within xy_goal_tolerance, then yaw_goal_tolerance.

    Stateful: once the robot has been within the xy tolerance it only waits for the heading
    (it may drift out of the xy tolerance while turning in place)."""

    def __init__(self, param: ParamGetter) -> None:
        self.xy_goal_tolerance = float(param('xy_goal_tolerance', 0.25))
        self.yaw_goal_tolerance = float(param('yaw_goal_tolerance', 0.25))
        self.stateful = bool(param('stateful', True))
        self.symmetric_yaw_tolerance = bool(param('symmetric_yaw_tolerance', False))
        self.check_xy = True

    def reset(self) -> None:
        self.check_xy = True

    def is_goal_reached(self, pose: Pose2D, goal: Pose2D, velocity: Pose2D) -> bool:
        if self.check_xy:
            if (pose[0] - goal[0]) ** 2 + (pose[1] - goal[1]) ** 2 > \
                    self.xy_goal_tolerance ** 2:
                return False
            if self.stateful:
                self.check_xy = False
        dyaw = abs(shortest_angular_distance(pose[2], goal[2]))
        if self.symmetric_yaw_tolerance:
            dyaw = min(dyaw, abs(shortest_angular_distance(pose[2], goal[2] + math.pi)))
        return dyaw <= self.yaw_goal_tolerance

    def tolerances(self) -> tuple[float, float]:
        """getTolerances: (xy, yaw)."""
        return self.xy_goal_tolerance, self.yaw_goal_tolerance


class StoppedGoalChecker(SimpleGoalChecker):
    """nav2_controller::StoppedGoalChecker: the simple checker, and the robot has stopped."""

    def __init__(self, param: ParamGetter) -> None:
        super().__init__(param)
        self.rot_stopped_velocity = float(param('rot_stopped_velocity', 0.25))
        self.trans_stopped_velocity = float(param('trans_stopped_velocity', 0.25))

    def is_goal_reached(self, pose: Pose2D, goal: Pose2D, velocity: Pose2D) -> bool:
        if not super().is_goal_reached(pose, goal, velocity):
            return False
        return abs(velocity[2]) <= self.rot_stopped_velocity and \
            math.hypot(velocity[0], velocity[1]) <= self.trans_stopped_velocity


class SimpleProgressChecker:
    """nav2_controller::SimpleProgressChecker: the robot must move required_movement_radius
    within movement_time_allowance seconds, or the goal fails to make progress."""

    def __init__(self, param: ParamGetter, now: Callable[[], float]) -> None:
        self.required_movement_radius = float(param('required_movement_radius', 0.5))
        self.movement_time_allowance = float(param('movement_time_allowance', 10.0))
        self._now = now
        self._baseline: Pose2D | None = None
        self._baseline_time = 0.0

    def reset(self) -> None:
        self._baseline = None

    def check(self, pose: Pose2D) -> bool:
        if self._baseline is None or self._moved_enough(pose):
            self._baseline, self._baseline_time = pose, self._now()
            return True
        return not (self._now() - self._baseline_time > self.movement_time_allowance)

    def _moved_enough(self, pose: Pose2D) -> bool:
        return math.hypot(pose[0] - self._baseline[0], pose[1] - self._baseline[1]) > \
            self.required_movement_radius


class PoseProgressChecker(SimpleProgressChecker):
    """nav2_controller::PoseProgressChecker: turning in place by required_movement_angle
    counts as progress too."""

    def __init__(self, param: ParamGetter, now: Callable[[], float]) -> None:
        super().__init__(param, now)
        self.required_movement_angle = float(param('required_movement_angle', 0.5))

    def _moved_enough(self, pose: Pose2D) -> bool:
        return super()._moved_enough(pose) or abs(shortest_angular_distance(
            self._baseline[2], pose[2])) > self.required_movement_angle


GOAL_CHECKERS = {'nav2_controller::SimpleGoalChecker': SimpleGoalChecker,
                 'nav2_controller::StoppedGoalChecker': StoppedGoalChecker}
PROGRESS_CHECKERS = {'nav2_controller::SimpleProgressChecker': SimpleProgressChecker,
                     'nav2_controller::PoseProgressChecker': PoseProgressChecker}
