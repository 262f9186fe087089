"""nav2_behaviors::Spin: turn in place by target_yaw (rad, the sign is the direction)."""

from __future__ import annotations

import math
from typing import Any

from nav2_msgs.action import Spin as SpinAction
from rclpy.duration import Duration
from rclpy.time import Time

from nav2_behaviors.motion import spin_poses_ahead, spin_speed, yaw_step
from nav2_behaviors.timed_behavior import ResultStatus, Status, TimedBehavior, declared

Result = SpinAction.Result


class Spin(TimedBehavior):
    action_type = SpinAction

    def __init__(self) -> None:
        super().__init__()
        self.feedback = SpinAction.Feedback()
        self.simulate_ahead_time = 2.0
        self.max_rotational_vel = 1.0
        self.min_rotational_vel = 0.4
        self.rotational_acc_lim = 3.2
        self.cmd_yaw = self.prev_yaw = self.relative_yaw = 0.0
        self.time_allowance = Duration()
        self.end_time: Time | None = None

    def on_configure(self) -> None:
        self.simulate_ahead_time = declared(self.node, 'simulate_ahead_time', 2.0)
        self.max_rotational_vel = declared(self.node, 'max_rotational_vel', 1.0)
        self.min_rotational_vel = declared(self.node, 'min_rotational_vel', 0.4)
        self.rotational_acc_lim = declared(self.node, 'rotational_acc_lim', 3.2)

    def on_run(self, goal: Any) -> ResultStatus:
        pose = self.current_pose()
        if pose is None:
            self.logger.error('Current robot pose is not available.')
            return ResultStatus(Status.FAILED, Result.TF_ERROR)
        if not math.isfinite(goal.target_yaw):
            self.logger.error(f'target_yaw must be a finite angle in rad, got {goal.target_yaw}')
            return ResultStatus(Status.FAILED, Result.UNKNOWN)
        self.prev_yaw = pose[2]
        self.relative_yaw = 0.0
        self.cmd_yaw = goal.target_yaw
        self.logger.info(f'Turning {self.cmd_yaw:0.2f} for spin behavior.')
        self.time_allowance = Duration.from_msg(goal.time_allowance)
        self.end_time = self.now() + self.time_allowance
        return ResultStatus(Status.SUCCEEDED)

    def on_cycle_update(self) -> ResultStatus:
        remaining_time = (self.end_time - self.now()).nanoseconds
        if remaining_time < 0 and self.time_allowance.nanoseconds > 0:
            self.stop_robot()
            self.logger.warning(
                'Exceeded time allowance before reaching the Spin goal - Exiting Spin')
            return ResultStatus(Status.FAILED, Result.TIMEOUT)
        pose = self.current_pose()
        if pose is None:
            self.logger.error('Current robot pose is not available.')
            return ResultStatus(Status.FAILED, Result.TF_ERROR)
        self.relative_yaw += yaw_step(self.prev_yaw, pose[2])
        self.prev_yaw = pose[2]
        self.feedback.angular_distance_traveled = float(self.relative_yaw)
        self.action_server.publish_feedback(self.feedback)
        remaining_yaw = abs(self.cmd_yaw) - abs(self.relative_yaw)
        if remaining_yaw < 1e-6:
            self.stop_robot()
            return ResultStatus(Status.SUCCEEDED)
        speed = math.copysign(spin_speed(remaining_yaw, self.rotational_acc_lim,
                                         self.min_rotational_vel, self.max_rotational_vel),
                              self.cmd_yaw)
        ahead = spin_poses_ahead(pose, speed, self.relative_yaw, self.cycle_frequency,
                                 self.simulate_ahead_time)
        if not self.collision_free(ahead):
            self.stop_robot()
            self.logger.warning('Collision Ahead - Exiting Spin')
            return ResultStatus(Status.FAILED, Result.COLLISION_AHEAD)
        self.publish_velocity(0.0, 0.0, speed)
        return ResultStatus(Status.RUNNING)
