"""`ros2 run dummy_sensors dummy_laser`: a fake 270-degree laser (a Hokuyo's 0.25-degree
steps, 1081 ranges) on `scan` at 30 Hz, in frame single_rrbot_hokuyo_link; every range is
|sin(t)| m, so the scan swells and shrinks around the sensor."""

from __future__ import annotations

import math
import sys

from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.node import Node
from sensor_msgs.msg import LaserScan

# The scanner's geometry in its own units (1/10000 degree), as the upstream demo gives it.
ANGLE_RESOLUTION = 2500
START_ANGLE = -450000
STOP_ANGLE = 2250000
SCAN_FREQUENCY = 2500


class DummyLaser(Node):
    def __init__(self) -> None:
        super().__init__('dummy_laser')
        self._pub = self.create_publisher(LaserScan, 'scan', 10)
        span = STOP_ANGLE - START_ANGLE
        count = span // ANGLE_RESOLUTION + (1 if span % ANGLE_RESOLUTION == 0 else 0)
        msg = LaserScan()
        msg.header.frame_id = 'single_rrbot_hokuyo_link'
        msg.time_increment = 0.0
        msg.angle_increment = math.radians(ANGLE_RESOLUTION / 10000.0)
        # The scanner counts from -45 to 225 degrees: less 90, its 270 degrees face +x.
        msg.angle_min = math.radians(START_ANGLE / 10000.0) - math.pi / 2
        msg.angle_max = math.radians(STOP_ANGLE / 10000.0) - math.pi / 2
        msg.scan_time = 100.0 / SCAN_FREQUENCY
        msg.range_min, msg.range_max = 0.0, 10.0
        self._msg, self._count, self._phase = msg, count, 0.0
        log = self.get_logger()
        log.info(f'angle inc:\t{msg.angle_increment:f}')
        log.info(f'scan size:\t{count}')
        log.info(f'scan time increment: \t{msg.time_increment:f}')
        self.create_timer(1.0 / 30.0, self._tick)

    def _tick(self) -> None:
        self._phase += 0.1
        self._msg.ranges = [abs(math.sin(self._phase))] * self._count
        self._msg.header.stamp = self.get_clock().now().to_msg()
        self._pub.publish(self._msg)


def main() -> int:
    with ros_session() as stop:
        spin_until_stopped(DummyLaser(), stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
