"""nav2_behaviors::DriveOnHeading and nav2_behaviors::BackUp: straight along the robot's
heading for target.x metres at `speed`, checking the local costmap ahead."""

from __future__ import annotations

import math
from typing import Any

from nav2_msgs.action import BackUp as BackUpAction
from nav2_msgs.action import DriveOnHeading as DriveOnHeadingAction
from rclpy.duration import Duration
from rclpy.time import Time

from nav2_behaviors.motion import Pose2D, drive_poses_ahead
from nav2_behaviors.timed_behavior import ResultStatus, Status, TimedBehavior, declared


class DriveOnHeading(TimedBehavior):
    action_type: Any = DriveOnHeadingAction
    label = 'DriveOnHeading'

    def __init__(self) -> None:
        super().__init__()
        self.feedback = self.action_type.Feedback()
        self.simulate_ahead_time = 2.0
        self.command_x = self.command_speed = 0.0
        self.time_allowance = Duration()
        self.end_time: Time | None = None
        self.initial_pose: Pose2D | None = None

    def on_configure(self) -> None:
        self.simulate_ahead_time = declared(self.node, 'simulate_ahead_time', 2.0)

    def _invalid(self, goal: Any) -> str | None:
        """The goal's first bad field, in one line (DriveOnHeading's own checks first)."""
        if goal.target.y != 0.0 or goal.target.z != 0.0:
            self.logger.info('DrivingOnHeading in Y and Z not supported, will only move in X.')
            return 'target'
        if not (math.isfinite(goal.target.x) and math.isfinite(goal.speed)):
            self.logger.error(f'target.x and speed must be finite, got {goal.target.x} and '
                              f'{goal.speed}')
            return 'target'
        if (goal.target.x > 0.0) != (goal.speed > 0.0):
            self.logger.error('Speed and command sign did not match')
            return 'speed'
        return None

    def commanded(self, goal: Any) -> tuple[float, float]:
        return goal.target.x, goal.speed

    def on_run(self, goal: Any) -> ResultStatus:
        Result = self.action_type.Result
        if self._invalid(goal) is not None:
            return ResultStatus(Status.FAILED, Result.INVALID_INPUT)
        self.command_x, self.command_speed = self.commanded(goal)
        self.time_allowance = Duration.from_msg(goal.time_allowance)
        self.end_time = self.now() + self.time_allowance
        self.initial_pose = self.current_pose()
        if self.initial_pose is None:
            self.logger.error('Initial robot pose is not available.')
            return ResultStatus(Status.FAILED, Result.TF_ERROR)
        return ResultStatus(Status.SUCCEEDED)

    def on_cycle_update(self) -> ResultStatus:
        Result = self.action_type.Result
        remaining_time = (self.end_time - self.now()).nanoseconds
        if remaining_time < 0 and self.time_allowance.nanoseconds > 0:
            self.stop_robot()
            self.logger.warning(
                f'Exceeded time allowance before reaching the {self.label} goal - Exiting '
                f'{self.label}')
            return ResultStatus(Status.FAILED, Result.TIMEOUT)
        pose = self.current_pose()
        if pose is None:
            self.logger.error('Current robot pose is not available.')
            return ResultStatus(Status.FAILED, Result.TF_ERROR)
        distance = math.hypot(self.initial_pose[0] - pose[0], self.initial_pose[1] - pose[1])
        self.feedback.distance_traveled = float(distance)
        self.action_server.publish_feedback(self.feedback)
        if distance >= abs(self.command_x):
            self.stop_robot()
            return ResultStatus(Status.SUCCEEDED)
        ahead = drive_poses_ahead(pose, self.command_speed, abs(self.command_x) - distance,
                                  self.cycle_frequency, self.simulate_ahead_time)
        if not self.collision_free(ahead):
            self.stop_robot()
            self.logger.warning(f'Collision Ahead - Exiting {self.label}')
            return ResultStatus(Status.FAILED, Result.COLLISION_AHEAD)
        self.publish_velocity(self.command_speed, 0.0, 0.0)
        return ResultStatus(Status.RUNNING)


class BackUp(DriveOnHeading):
    """DriveOnHeading backwards: target.x and speed are taken as magnitudes."""

    action_type = BackUpAction
    label = 'DriveOnHeading'  # upstream's BackUp reuses DriveOnHeading's lines

    def _invalid(self, goal: Any) -> str | None:
        if goal.target.y != 0.0 or goal.target.z != 0.0:
            self.logger.info('Backing up in Y and Z not supported, will only move in X.')
            return 'target'
        if not (math.isfinite(goal.target.x) and math.isfinite(goal.speed)):
            self.logger.error(f'target.x and speed must be finite, got {goal.target.x} and '
                              f'{goal.speed}')
            return 'target'
        return None

    def commanded(self, goal: Any) -> tuple[float, float]:
        return -abs(goal.target.x), -abs(goal.speed)
