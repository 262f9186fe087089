"""draw_square: drive turtle1 along a 2 m square, forever (the upstream tutorial)."""

from __future__ import annotations

import math
import sys
from enum import Enum

from geometry_msgs.msg import Twist
from node_runtime.rclcpp_parity import RclcppParameters, declare_rclcpp_parameters
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.node import Node
from std_srvs.srv import Empty
from turtlesim.msg import Pose

from turtlesim_py.turtle import TOPIC_QOS

PI = 3.141592


class State(Enum):
    FORWARD = 0
    STOP_FORWARD = 1
    TURN = 2
    STOP_TURN = 3


def has_reached_goal(pose: Pose, goal: Pose) -> bool:
    return (abs(pose.x - goal.x) < 0.1 and abs(pose.y - goal.y) < 0.1
            and abs(pose.theta - goal.theta) < 0.01)


def has_stopped(pose: Pose) -> bool:
    return pose.angular_velocity < 0.0001 and pose.linear_velocity < 0.0001


def wrap_heading(theta: float) -> float:
    """fmod(theta + pi/2, 2pi) wrapped into [-pi, pi) as upstream does."""
    value = math.fmod(theta + PI / 2, 2 * PI)
    if value >= PI:
        value -= 2 * PI
    elif value < -PI:
        value += 2 * PI
    return value


class DrawSquare(RclcppParameters, Node):
    def __init__(self) -> None:
        super().__init__('draw_square')
        declare_rclcpp_parameters(self)  # upstream's is an rclcpp node
        self.twist_pub = self.create_publisher(Twist, 'turtle1/cmd_vel', TOPIC_QOS)
        self.create_subscription(Pose, 'turtle1/pose', self._on_pose, TOPIC_QOS)
        self.reset_client = self.create_client(Empty, 'reset')
        self.reset_client.call_async(Empty.Request())  # fire and forget, as upstream
        self.pose: Pose | None = None
        self.goal: Pose | None = None
        self.state = State.FORWARD
        self.create_timer(0.016, self._on_tick)

    def _on_pose(self, pose: Pose) -> None:
        self.pose = pose

    def _log_goal(self) -> None:
        self.get_logger().info(f'New goal [{self.goal.x:f} {self.goal.y:f}, {self.goal.theta:f}]')

    def _forward_goal(self) -> None:
        pose = self.pose
        self.goal = Pose(x=pose.x + 2 * math.cos(pose.theta), y=pose.y + 2 * math.sin(pose.theta),
                         theta=pose.theta)
        self._log_goal()

    def _publish(self, linear: float = 0.0, angular: float = 0.0) -> None:
        twist = Twist()
        twist.linear.x = linear
        twist.angular.z = angular
        self.twist_pub.publish(twist)

    def _on_tick(self) -> None:
        if self.pose is None:
            return
        if self.goal is None:
            self._forward_goal()
            return
        pose = self.pose
        if self.state == State.FORWARD:
            if has_reached_goal(pose, self.goal):
                self.state = State.STOP_FORWARD
                self._publish()
            else:
                self._publish(linear=1.0)
        elif self.state == State.STOP_FORWARD:
            if has_stopped(pose):
                self.get_logger().info('Reached goal')
                self.goal = Pose(x=self.goal.x, y=self.goal.y, theta=wrap_heading(pose.theta))
                self.state = State.TURN
                self._log_goal()
            else:
                self._publish()
        elif self.state == State.TURN:
            if has_reached_goal(pose, self.goal):
                self.state = State.STOP_TURN
                self._publish()
            else:
                self._publish(angular=0.4)
        elif has_stopped(pose):
            self.get_logger().info('Reached goal')
            self.state = State.FORWARD
            self._forward_goal()
        else:
            self._publish()


def main(argv: list[str] | None = None) -> int:
    with ros_session(sys.argv if argv is None else argv) as stop:
        spin_until_stopped(DrawSquare(), stop)
    return 0
