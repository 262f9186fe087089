"""nav2_behaviors::TimedBehavior: the action server and cycle loop every behaviour shares.

A behaviour plugin implements on_run(goal) (the initial checks) and on_cycle_update() (one
cycle: feedback, then SUCCEEDED, FAILED or RUNNING); this class runs it at cycle_frequency
(wall rate, as upstream's WallRate), stops the robot on cancel and failure, and ends the goal
with upstream's lines ("Running spin", "spin completed successfully", "Canceling spin", ...).
"""

from __future__ import annotations

import enum
import time
from dataclasses import dataclass
from typing import Any

from geometry_msgs.msg import Twist, TwistStamped
from nav2_util.parameters import declare_checked
from rclpy.duration import Duration
from rclpy.time import Time
from tf2_ros import Buffer, TransformException

from nav2_behaviors.costmap_topic_collision_checker import CostmapTopicCollisionChecker
from nav2_behaviors.motion import Pose2D, yaw_of
from nav2_behaviors.simple_action_server import SimpleActionServer


class Status(enum.IntEnum):
    SUCCEEDED = 1
    FAILED = 2
    RUNNING = 3


@dataclass
class ResultStatus:
    status: Status
    error_code: int = 0


class CostmapInfoType(enum.IntEnum):
    NONE = 0
    LOCAL = 1
    GLOBAL = 2
    BOTH = 3


def declared(node: Any, name: str, default: Any) -> Any:
    """declare_parameter_if_not_declared + get_parameter (a reconfigure declares nothing)."""
    if node.has_parameter(name):
        return node.get_parameter(name).value
    return declare_checked(node, name, default)


class TimedBehavior:
    """Base of Spin, BackUp, DriveOnHeading, Wait and AssistedTeleop."""

    action_type: Any = None
    resource_info = CostmapInfoType.LOCAL

    def __init__(self) -> None:
        self.node: Any = None
        self.name = ''
        self.tf: Buffer | None = None
        self.local_collision_checker: CostmapTopicCollisionChecker | None = None
        self.global_collision_checker: CostmapTopicCollisionChecker | None = None
        self.action_server: SimpleActionServer | None = None
        self.vel_pub: Any = None
        self.stamped = False
        self.enabled = False
        self.cycle_frequency = 10.0
        self.local_frame = 'odom'
        self.global_frame = 'map'
        self.robot_base_frame = 'base_link'
        self.transform_tolerance = 0.1
        self.elapsed_time = Duration()

    # --- what the plugin overrides -------------------------------------------------------
    def on_run(self, goal: Any) -> ResultStatus:
        raise NotImplementedError

    def on_cycle_update(self) -> ResultStatus:
        raise NotImplementedError

    def on_configure(self) -> None:
        """Declare the plugin's own parameters."""

    def on_cleanup(self) -> None:
        """Drop what on_configure made."""

    def on_action_completion(self, result: Any) -> None:
        """Reset per-goal state when a goal ends."""

    # --- nav2_core::Behavior -------------------------------------------------------------
    def configure(self, node: Any, name: str, tf: Buffer,
                  local_collision_checker: CostmapTopicCollisionChecker | None,
                  global_collision_checker: CostmapTopicCollisionChecker | None) -> None:
        self.node = node
        self.logger = node.get_logger()
        self.logger.info(f'Configuring {name}')
        self.name = name
        self.tf = tf
        self.cycle_frequency = node.get_parameter('cycle_frequency').value
        self.local_frame = node.get_parameter('local_frame').value
        self.global_frame = node.get_parameter('global_frame').value
        self.robot_base_frame = node.get_parameter('robot_base_frame').value
        self.transform_tolerance = node.get_parameter('transform_tolerance').value
        result_timeout = declared(node, 'action_server_result_timeout', 10.0)
        self.action_server = SimpleActionServer(node, self.action_type, name, self.execute,
                                                result_timeout=result_timeout)
        self.local_collision_checker = local_collision_checker
        self.global_collision_checker = global_collision_checker
        # nav2_util::TwistPublisher: Twist unless enable_stamped_cmd_vel
        self.stamped = declared(node, 'enable_stamped_cmd_vel', False)
        self.vel_pub = node.create_lifecycle_publisher(
            TwistStamped if self.stamped else Twist, 'cmd_vel', 1)
        self.on_configure()

    def cleanup(self) -> None:
        if self.action_server is not None:
            self.action_server.destroy()
        if self.vel_pub is not None:
            self.node.destroy_lifecycle_publisher(self.vel_pub)
        self.action_server = self.vel_pub = None
        self.on_cleanup()

    def activate(self) -> None:
        self.logger.info(f'Activating {self.name}')
        self.action_server.activate()
        self.enabled = True

    def deactivate(self) -> None:
        self.enabled = False
        self.action_server.deactivate()

    # --- the loop ------------------------------------------------------------------------
    def now(self) -> Time:
        return self.node.get_clock().now()

    def execute(self) -> None:
        self.logger.info(f'Running {self.name}')
        if not self.enabled:
            self.logger.warning('Called while inactive, ignoring request.')
            return
        server = self.action_server
        result = self.action_type.Result()
        goal = server.get_current_goal()
        if goal is None:
            return
        status = self.on_run(goal)
        if status.status != Status.SUCCEEDED:
            self.logger.info(f'Initial checks failed for {self.name}')
            result.error_code = status.error_code
            server.terminate_current(result)
            return
        start = self.now()
        period = 1.0 / self.cycle_frequency
        next_cycle = time.monotonic()
        while self.enabled:
            self.elapsed_time = self.now() - start
            if server.is_preempt_requested():
                self.logger.error(
                    f'Received a preemption request for {self.name}, however feature is '
                    'currently not implemented. Aborting and stopping.')
                self.stop_robot()
                result.total_elapsed_time = (self.now() - start).to_msg()
                self.on_action_completion(result)
                server.terminate_current(result)
                return
            if server.is_cancel_requested():
                self.logger.info(f'Canceling {self.name}')
                self.stop_robot()
                result.total_elapsed_time = self.elapsed_time.to_msg()
                self.on_action_completion(result)
                server.terminate_all(result)
                return
            status = self.on_cycle_update()
            if status.status == Status.SUCCEEDED:
                self.logger.info(f'{self.name} completed successfully')
                result.total_elapsed_time = (self.now() - start).to_msg()
                self.on_action_completion(result)
                server.succeeded_current(result)
                return
            if status.status == Status.FAILED:
                self.logger.warning(f'{self.name} failed')
                result.total_elapsed_time = (self.now() - start).to_msg()
                result.error_code = status.error_code
                self.on_action_completion(result)
                server.terminate_current(result)
                return
            # WallRate: the next cycle one period after the last, or now when late
            next_cycle = max(next_cycle + period, time.monotonic())
            time.sleep(max(0.0, next_cycle - time.monotonic()))
        self.stop_robot()  # deactivated while running: the action server ends the goal

    def publish_velocity(self, vx: float, vy: float, wz: float) -> None:
        twist = Twist()
        twist.linear.x, twist.linear.y, twist.angular.z = float(vx), float(vy), float(wz)
        if self.stamped:
            msg = TwistStamped()
            msg.header.frame_id = self.robot_base_frame
            msg.header.stamp = self.now().to_msg()
            msg.twist = twist
            self.vel_pub.publish(msg)
        else:
            self.vel_pub.publish(twist)

    def stop_robot(self) -> None:
        self.publish_velocity(0.0, 0.0, 0.0)

    def current_pose(self) -> Pose2D | None:
        """nav2_util::getCurrentPose: robot_base_frame in local_frame from the latest TF."""
        try:
            t = self.tf.lookup_transform(self.local_frame, self.robot_base_frame, Time(),
                                         Duration(seconds=self.transform_tolerance))
        except (TransformException, TypeError) as error:
            self.logger.error(
                f'No Transform available Error looking up target frame: {error}',
                throttle_duration_sec=1.0)
            return None
        tr = t.transform
        return (tr.translation.x, tr.translation.y,
                yaw_of(tr.rotation.x, tr.rotation.y, tr.rotation.z, tr.rotation.w))

    def collision_free(self, poses: Any) -> bool:
        """The local costmap's verdict on simulated poses (the first check fetches)."""
        fetch = True
        for pose in poses:
            if not self.local_collision_checker.is_collision_free(pose, fetch):
                return False
            fetch = False
        return True
