"""The baseline for the pose-latency benchmark: the smallest rclpy node publishing a
turtlesim/msg/Pose at turtlesim's rate (62.5 Hz) from a ROS timer, same QoS."""

import rclpy
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.qos import QoSProfile, ReliabilityPolicy
from turtlesim.msg import Pose

PERIOD_S = 0.016


class BaselinePublisher(Node):
    def __init__(self) -> None:
        super().__init__('baseline_pose_publisher')
        qos = QoSProfile(depth=7, reliability=ReliabilityPolicy.RELIABLE)
        self.publisher = self.create_publisher(Pose, 'baseline_pose', qos)
        self.pose = Pose()
        self.create_timer(PERIOD_S, self.on_timer)

    def on_timer(self) -> None:
        self.pose.x += 0.01
        self.publisher.publish(self.pose)


def main() -> None:
    try:
        rclpy.init()
        rclpy.spin(BaselinePublisher())
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
