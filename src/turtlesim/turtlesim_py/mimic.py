"""mimic: turn the poses of one turtle into velocity commands for another."""

from __future__ import annotations

import sys

from geometry_msgs.msg import Twist
from node_runtime.rclcpp_parity import RclcppParameters, declare_rclcpp_parameters
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.node import Node
from turtlesim.msg import Pose

from turtlesim_py.turtle import TOPIC_QOS


def pose_to_twist(pose: Pose) -> Twist:
    twist = Twist()
    twist.linear.x = float(pose.linear_velocity)
    twist.angular.z = float(pose.angular_velocity)
    return twist


class Mimic(RclcppParameters, Node):
    def __init__(self) -> None:
        super().__init__('turtle_mimic')
        declare_rclcpp_parameters(self)  # upstream's is an rclcpp node
        self.twist_pub = self.create_publisher(Twist, 'output/cmd_vel', TOPIC_QOS)
        self.create_subscription(Pose, 'input/pose', self._on_pose, TOPIC_QOS)

    def _on_pose(self, pose: Pose) -> None:
        self.twist_pub.publish(pose_to_twist(pose))


def main(argv: list[str] | None = None) -> int:
    with ros_session(sys.argv if argv is None else argv) as stop:
        spin_until_stopped(Mimic(), stop)
    return 0
