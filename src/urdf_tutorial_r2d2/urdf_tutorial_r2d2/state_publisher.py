"""state_publisher: walks the r2d2 model in a circle (the "Using URDF with
robot_state_publisher (Python)" page): /joint_states for swivel, tilt and periscope, and
the odom -> axis transform on /tf, 30 times a second."""

from __future__ import annotations

from math import cos, pi, sin

from geometry_msgs.msg import Quaternion, TransformStamped
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.node import Node
from rclpy.qos import QoSProfile
from sensor_msgs.msg import JointState
from tf2_ros import TransformBroadcaster

DEGREE = pi / 180.0


def euler_to_quaternion(roll: float, pitch: float, yaw: float) -> Quaternion:
    cr, sr = cos(roll / 2), sin(roll / 2)
    cp, sp = cos(pitch / 2), sin(pitch / 2)
    cy, sy = cos(yaw / 2), sin(yaw / 2)
    return Quaternion(x=sr * cp * cy - cr * sp * sy, y=cr * sp * cy + sr * cp * sy,
                      z=cr * cp * sy - sr * sp * cy, w=cr * cp * cy + sr * sp * sy)


class StatePublisher(Node):
    def __init__(self) -> None:
        super().__init__('state_publisher')
        qos = QoSProfile(depth=10)
        self.joint_pub = self.create_publisher(JointState, 'joint_states', qos)
        self.broadcaster = TransformBroadcaster(self, qos=qos)
        self.tilt, self.tinc = 0.0, DEGREE
        self.swivel, self.angle = 0.0, 0.0
        self.height, self.hinc = 0.0, 0.005
        self.create_timer(1 / 30, self.on_timer)
        self.get_logger().info(f'{self.get_name()} started')

    def on_timer(self) -> None:
        now = self.get_clock().now().to_msg()
        joints = JointState()
        joints.header.stamp = now
        joints.name = ['swivel', 'tilt', 'periscope']
        joints.position = [self.swivel, self.tilt, self.height]
        odom = TransformStamped()
        odom.header.stamp = now
        odom.header.frame_id = 'odom'
        odom.child_frame_id = 'axis'
        odom.transform.translation.x = cos(self.angle) * 2
        odom.transform.translation.y = sin(self.angle) * 2
        odom.transform.translation.z = 0.7
        odom.transform.rotation = euler_to_quaternion(0, 0, self.angle + pi / 2)
        self.joint_pub.publish(joints)
        self.broadcaster.sendTransform(odom)
        # The next pose: tilt between -0.5 and 0, periscope between 0 and 0.2.
        self.tilt += self.tinc
        if self.tilt < -0.5 or self.tilt > 0.0:
            self.tinc *= -1
        self.height += self.hinc
        if self.height > 0.2 or self.height < 0.0:
            self.hinc *= -1
        self.swivel += DEGREE
        self.angle += DEGREE / 4


def main(args: list[str] | None = None) -> None:
    with ros_session(args) as stop:
        spin_until_stopped(StatePublisher(), stop)


if __name__ == '__main__':
    main()
