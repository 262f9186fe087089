"""Spawn turtle2 through /spawn, then drive it towards `target_frame` (default turtle1).

Once a second the listener asks tf2 where the target frame is, seen from turtle2, and
sends turtle2 a Twist that turns it towards that point and drives it at half the distance
per second. The "Using time" and "Traveling in time" variants only change the lookup
(turtle_tf2_listener_using_time.py, turtle_tf2_listener_time_travel.py).
"""

from __future__ import annotations

import math
import sys

import rclpy
from geometry_msgs.msg import TransformStamped, Twist
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.node import Node
from rclpy.task import Future
from tf2_ros import TransformException
from tf2_ros.buffer import Buffer
from tf2_ros.transform_listener import TransformListener
from turtlesim.srv import Spawn

from turtle_tf2_py.parameters import declare_frame


class FrameListener(Node):
    waits_for_transforms = False  # lookups with a timeout (the "Using time" variants)

    def __init__(self) -> None:
        super().__init__('turtle_tf2_frame_listener')
        self.target_frame = declare_frame(self, 'target_frame', 'turtle1')

        self.tf_buffer = Buffer()
        # The "Using time" variants wait inside the timer callback for /tf data: their
        # listener spins on a thread of its own (spin_thread), as C++'s listener always does.
        self.tf_listener = TransformListener(self.tf_buffer, self,
                                             spin_thread=self.waits_for_transforms)

        self.spawner = self.create_client(Spawn, 'spawn')
        self.turtle_spawning_service_ready = False  # the spawn request was sent
        self.turtle_spawned = False  # and answered
        self.result: Future | None = None

        self.publisher = self.create_publisher(Twist, 'turtle2/cmd_vel', 1)
        self.timer = self.create_timer(1.0, self.on_timer)

    def lookup(self, to_frame: str, from_frame: str) -> TransformStamped:
        """Where `from_frame` is in `to_frame`: the latest transform tf2 has (time 0)."""
        return self.tf_buffer.lookup_transform(to_frame, from_frame, rclpy.time.Time())

    def on_timer(self) -> None:
        from_frame_rel = self.target_frame
        to_frame_rel = 'turtle2'
        if not self.turtle_spawning_service_ready:
            self.request_spawn()
        elif not self.turtle_spawned:
            assert self.result is not None
            if self.result.done():
                self.get_logger().info(f'Successfully spawned {self.result.result().name}')
                self.turtle_spawned = True
            else:
                self.get_logger().info('Spawn is not finished')
        else:
            try:
                t = self.lookup(to_frame_rel, from_frame_rel)
            except TransformException as ex:
                self.get_logger().info(
                    f'Could not transform {to_frame_rel} to {from_frame_rel}: {ex}')
                return
            self.publisher.publish(self.follow(t))

    def request_spawn(self) -> None:
        if not self.spawner.service_is_ready():
            self.get_logger().info('Service is not ready')
            return
        request = Spawn.Request()
        request.name = 'turtle2'
        request.x = 4.0
        request.y = 2.0
        request.theta = 0.0
        self.result = self.spawner.call_async(request)
        self.turtle_spawning_service_ready = True

    @staticmethod
    def follow(t: TransformStamped) -> Twist:
        """Turn towards the target and drive at half its distance per second."""
        x, y = t.transform.translation.x, t.transform.translation.y
        msg = Twist()
        scale_rotation_rate = 1.0
        msg.angular.z = scale_rotation_rate * math.atan2(y, x)
        scale_forward_speed = 0.5
        msg.linear.x = scale_forward_speed * math.sqrt(x ** 2 + y ** 2)
        return msg


def run(node_class: type[FrameListener]) -> int:
    with ros_session() as stop:
        spin_until_stopped(node_class(), stop)
    return 0


def main() -> int:
    return run(FrameListener)


if __name__ == '__main__':
    sys.exit(main())
