"""`ros2 run slam_toolbox async_slam_toolbox_node`: mapping at the pace the machine allows.

Only the newest scan waits for the worker: a scan that arrives while another is still
waiting replaces it, and the one replaced is counted as dropped (said once, then the count
in the throttled line). Upstream's async node gets the same effect from its message
filter's queue of scan_queue_size (1).
"""

from __future__ import annotations

import sys
import threading

from node_runtime.spinning import ros_session, spin_until_stopped
from sensor_msgs.msg import LaserScan

from slam_toolbox_py.slam_toolbox_node import SlamToolbox


class AsynchronousSlamToolbox(SlamToolbox):
    def __init__(self) -> None:
        super().__init__()
        self._pending: LaserScan | None = None
        self._ready = threading.Condition()

    def enqueue(self, msg: LaserScan) -> None:
        with self._ready:
            if self._pending is not None:
                self.dropped += 1
                if self.dropped == 1:
                    self.get_logger().warning(
                        'Dropping scans: they arrive faster than they are processed (the '
                        'newest is kept; the count is in the debug log)')
                self.get_logger().debug(f'Dropped {self.dropped} scans so far')
            self._pending = msg
            self._ready.notify()

    def wake_worker(self) -> None:
        with self._ready:
            self._ready.notify_all()

    def next_scan(self) -> LaserScan | None:
        with self._ready:
            if self._pending is None:
                self._ready.wait(timeout=0.1)
            msg, self._pending = self._pending, None
        return msg


def main(args: list[str] | None = None) -> int:
    with ros_session(args) as stop:
        node = AsynchronousSlamToolbox()
        spin_until_stopped(node, stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
