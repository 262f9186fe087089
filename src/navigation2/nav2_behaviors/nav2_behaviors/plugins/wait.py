"""nav2_behaviors::Wait: do nothing for `time`, with time_left as feedback."""

from __future__ import annotations

from typing import Any

from nav2_msgs.action import Wait as WaitAction
from rclpy.duration import Duration
from rclpy.time import Time

from nav2_behaviors.timed_behavior import CostmapInfoType, ResultStatus, Status, TimedBehavior


class Wait(TimedBehavior):
    action_type = WaitAction
    resource_info = CostmapInfoType.NONE

    def __init__(self) -> None:
        super().__init__()
        self.feedback = WaitAction.Feedback()
        self.wait_end: Time | None = None

    def on_run(self, goal: Any) -> ResultStatus:
        self.wait_end = self.now() + Duration.from_msg(goal.time)
        return ResultStatus(Status.SUCCEEDED)

    def on_cycle_update(self) -> ResultStatus:
        left = self.wait_end - self.now()
        self.feedback.time_left = left.to_msg()
        self.action_server.publish_feedback(self.feedback)
        if left.nanoseconds > 0:
            return ResultStatus(Status.RUNNING)
        return ResultStatus(Status.SUCCEEDED)
