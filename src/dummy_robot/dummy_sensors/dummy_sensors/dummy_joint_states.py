"""`ros2 run dummy_sensors dummy_joint_states`: both joints of the single RRbot swinging
together, position sin(t) rad, on `joint_states` at 50 Hz."""

from __future__ import annotations

import math
import sys

from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.node import Node
from sensor_msgs.msg import JointState

JOINTS = ('single_rrbot_joint1', 'single_rrbot_joint2')


class DummyJointStates(Node):
    def __init__(self) -> None:
        super().__init__('dummy_joint_states')
        self._pub = self.create_publisher(JointState, 'joint_states', 10)
        self._phase = 0.0
        self.create_timer(1.0 / 50.0, self._tick)

    def _tick(self) -> None:
        self._phase += 0.1
        msg = JointState(name=list(JOINTS), position=[math.sin(self._phase)] * len(JOINTS))
        msg.header.stamp = self.get_clock().now().to_msg()
        self._pub.publish(msg)


def main() -> int:
    with ros_session() as stop:
        spin_until_stopped(DummyJointStates(), stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
