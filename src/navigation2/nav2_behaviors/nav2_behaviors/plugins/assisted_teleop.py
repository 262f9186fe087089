"""nav2_behaviors::AssistedTeleop: pass `cmd_vel_teleop` on to cmd_vel, slowed down (or
stopped) when the local costmap shows a collision within projection_time; ends on
`preempt_teleop` (std_msgs/Empty) or when time_allowance runs out."""

from __future__ import annotations

from typing import Any

from geometry_msgs.msg import Twist, TwistStamped
from nav2_msgs.action import AssistedTeleop as AssistedTeleopAction
from rclpy.duration import Duration
from rclpy.qos import qos_profile_system_default
from rclpy.time import Time
from std_msgs.msg import Empty

from nav2_behaviors.motion import teleop_scale
from nav2_behaviors.timed_behavior import ResultStatus, Status, TimedBehavior, declared

Result = AssistedTeleopAction.Result


class AssistedTeleop(TimedBehavior):
    action_type = AssistedTeleopAction

    def __init__(self) -> None:
        super().__init__()
        self.feedback = AssistedTeleopAction.Feedback()
        self.projection_time = 1.0
        self.simulation_time_step = 0.1
        self.teleop = Twist()
        self.preempt_teleop = False
        self.time_allowance = Duration()
        self.end_time: Time | None = None
        self._topic_handles: list[Any] = []

    def on_configure(self) -> None:
        node = self.node
        self.projection_time = declared(node, 'projection_time', 1.0)
        self.simulation_time_step = declared(node, 'simulation_time_step', 0.1)
        topic = declared(node, 'cmd_vel_teleop', 'cmd_vel_teleop')
        kind = TwistStamped if self.stamped else Twist
        self._topic_handles = [
            node.create_subscription(kind, topic, self._on_teleop, qos_profile_system_default),
            node.create_subscription(Empty, 'preempt_teleop', self._on_preempt_teleop,
                                     qos_profile_system_default)]

    def on_cleanup(self) -> None:
        for subscription in self._topic_handles:
            self.node.destroy_subscription(subscription)
        self._topic_handles = []

    def _on_teleop(self, msg: Any) -> None:
        self.teleop = msg.twist if isinstance(msg, TwistStamped) else msg

    def _on_preempt_teleop(self, _msg: Empty) -> None:
        self.preempt_teleop = True

    def on_run(self, goal: Any) -> ResultStatus:
        self.preempt_teleop = False
        self.time_allowance = Duration.from_msg(goal.time_allowance)
        self.end_time = self.now() + self.time_allowance
        return ResultStatus(Status.SUCCEEDED)

    def on_action_completion(self, result: Any) -> None:
        self.teleop = Twist()
        self.preempt_teleop = False

    def on_cycle_update(self) -> ResultStatus:
        self.feedback.current_teleop_duration = self.elapsed_time.to_msg()
        self.action_server.publish_feedback(self.feedback)
        remaining_time = (self.end_time - self.now()).nanoseconds
        if remaining_time < 0 and self.time_allowance.nanoseconds > 0:
            self.stop_robot()
            self.logger.warning(f'Exceeded time allowance before reaching the {self.name}goal '
                                f'- Exiting {self.name}')
            return ResultStatus(Status.FAILED, Result.TIMEOUT)
        if self.preempt_teleop:
            self.stop_robot()
            return ResultStatus(Status.SUCCEEDED)
        pose = self.current_pose()
        if pose is None:
            self.logger.error(f'Current robot pose is not available for {self.name}')
            return ResultStatus(Status.FAILED, Result.TF_ERROR)
        twist = self.teleop
        fetched = [False]

        def collides(projected: Any) -> bool:
            free = self.local_collision_checker.is_collision_free(projected, not fetched[0])
            fetched[0] = True
            return not free

        scale = teleop_scale(collides, pose, twist.linear.x, twist.linear.y, twist.angular.z,
                             self.simulation_time_step, self.projection_time)
        self.publish_velocity(twist.linear.x * scale, twist.linear.y * scale,
                              twist.angular.z * scale)
        return ResultStatus(Status.RUNNING)
