"""A real rclpy node standing in for turtlesim where the tests need control over it.

It publishes turtle1 poses along a scripted path at turtlesim's rate (62.5 Hz) and serves
/turtle1/set_pen, answering each request only after --set-pen-delay seconds. The service runs
in its own callback group on a multi-threaded executor, so a slow answer never delays a pose
(as in a turtlesim that is busy elsewhere). Each request is logged with wall-clock times:
    set_pen received r=255 g=0 b=0 width=3 off=0 at=<time.time()>
    set_pen answered at=<time.time()>
Run: python src/my_robot_controller/test/turtle_stand_in.py --path cross --set-pen-delay 0.5
"""

from __future__ import annotations

import argparse
import math
import sys
import time

import rclpy
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup
from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from turtlesim.msg import Pose
from turtlesim.srv import SetPen

TURTLE_QOS = QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=7,
                        reliability=ReliabilityPolicy.RELIABLE,
                        durability=DurabilityPolicy.VOLATILE)
TICK = 0.016


class TurtleStandIn(Node):
    def __init__(self, path: str, hold_x: float, period: float, delay: float) -> None:
        super().__init__('turtlesim')
        self.path, self.hold_x, self.period, self.delay = path, hold_x, period, delay
        self.started = time.monotonic()
        self.pose = self.create_publisher(Pose, '/turtle1/pose', TURTLE_QOS)
        self.create_timer(TICK, self.on_tick, callback_group=MutuallyExclusiveCallbackGroup())
        self.create_service(SetPen, '/turtle1/set_pen', self.on_set_pen,
                            callback_group=MutuallyExclusiveCallbackGroup())
        self.get_logger().info(f'stand-in ready: path={path} set_pen delay={delay} s')

    def x_at(self, t: float) -> float:
        if self.path == 'hold':
            return self.hold_x
        # 'cross': swing 1.5 m either side of x = 5.5, crossing it every period / 2 seconds.
        return 5.5 + 1.5 * math.sin(2 * math.pi * t / self.period)

    def on_tick(self) -> None:
        self.pose.publish(Pose(x=self.x_at(time.monotonic() - self.started), y=5.5))

    def on_set_pen(self, request: SetPen.Request, response: SetPen.Response) -> SetPen.Response:
        print(f'set_pen received r={request.r} g={request.g} b={request.b} '
              f'width={request.width} off={request.off} at={time.time():.6f}', flush=True)
        time.sleep(self.delay)  # a slow server; only this callback group waits
        print(f'set_pen answered at={time.time():.6f}', flush=True)
        return response


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument('--path', choices=['cross', 'hold'], default='cross')
    parser.add_argument('--hold-x', type=float, default=3.0)
    parser.add_argument('--period', type=float, default=2.0)
    parser.add_argument('--set-pen-delay', type=float, default=0.0)
    options = parser.parse_args()
    try:
        rclpy.init()
        node = TurtleStandIn(options.path, options.hold_x, options.period, options.set_pen_delay)
        executor = MultiThreadedExecutor(num_threads=3)
        executor.add_node(node)
        executor.spin()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        rclpy.try_shutdown()


if __name__ == '__main__':
    sys.exit(main())
