"""`ros2 run dummy_map_server dummy_map_server`: a 10 m x 10 m map (100 x 100 cells of
0.1 m, centred on the origin of frame world, all unknown) on `map` once a second, latched
(keep last 1, transient local) as a map server does. Each second one occupied cell with a
free cell either side moves one cell further along the grid."""

from __future__ import annotations

import sys

from nav_msgs.msg import OccupancyGrid
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile

UNKNOWN, FREE, OCCUPIED = -1, 0, 100


class DummyMapServer(Node):
    def __init__(self) -> None:
        super().__init__('dummy_map_server')
        self._pub = self.create_publisher(
            OccupancyGrid, 'map', QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL))
        msg = OccupancyGrid()
        msg.header.frame_id = 'world'
        msg.info.resolution = 0.1
        msg.info.width = msg.info.height = 100
        msg.info.origin.position.x = -msg.info.width * msg.info.resolution / 2
        msg.info.origin.position.y = -msg.info.height * msg.info.resolution / 2
        msg.info.origin.orientation.w = 1.0
        self._cells = [UNKNOWN] * (msg.info.width * msg.info.height)
        self._msg = msg
        self._left = 0  # the free cell before the occupied one
        self.create_timer(1.0, self._tick)

    def _tick(self) -> None:
        size = len(self._cells)
        for offset in range(3):  # the marks of the last tick back to unknown
            self._cells[(self._left + offset) % size] = UNKNOWN
        self._left += 1
        for offset, value in enumerate((FREE, OCCUPIED, FREE)):
            self._cells[(self._left + offset) % size] = value
        self._msg.data = self._cells
        self._msg.header.stamp = self.get_clock().now().to_msg()
        self._pub.publish(self._msg)


def main() -> int:
    with ros_session() as stop:
        spin_until_stopped(DummyMapServer(), stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
