"""`ros2 run slam_toolbox sync_slam_toolbox_node`: every scan is processed, in order.

Scans queue up for the worker however long it takes (upstream's warning past 10 waiting);
`slam_toolbox/clear_queue` empties the queue.
"""

from __future__ import annotations

import sys
import threading
from collections import deque

from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.lifecycle import State, TransitionCallbackReturn
from sensor_msgs.msg import LaserScan

from slam_toolbox.srv import ClearQueue
from slam_toolbox_py.slam_toolbox_node import SlamToolbox

QUEUE_LIMIT = 10_000  # scans: past this the oldest go (counted), not the process's memory


class SynchronousSlamToolbox(SlamToolbox):
    def __init__(self) -> None:
        super().__init__()
        self._queue: deque[LaserScan] = deque()
        self._ready = threading.Condition()

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        result = super().on_activate(state)
        self.handles.append(self.create_service(ClearQueue, 'slam_toolbox/clear_queue',
                                                self.on_clear_queue))
        return result

    def enqueue(self, msg: LaserScan) -> None:
        with self._ready:
            if len(self._queue) >= QUEUE_LIMIT:
                self._queue.popleft()
                self.dropped += 1
            self._queue.append(msg)
            self._ready.notify()

    def wake_worker(self) -> None:
        with self._ready:
            self._ready.notify_all()

    def next_scan(self) -> LaserScan | None:
        with self._ready:
            if not self._queue:
                self._ready.wait(timeout=0.1)
            if not self._queue:
                return None
            msg = self._queue.popleft()
            waiting = len(self._queue)
        if waiting > 10:
            self.get_logger().warning(
                f'Queue size has grown to: {waiting}. Recommend stopping until message is '
                'gone if online mapping.', throttle_duration_sec=5.0)
        return msg

    def on_clear_queue(self, request: ClearQueue.Request, response: ClearQueue.Response
                       ) -> ClearQueue.Response:
        with self._ready:
            self.get_logger().info(f'SynchronousSlamToolbox: Clearing all queued scans to '
                                   f'add to map ({len(self._queue)}).')
            self._queue.clear()
        response.status = True
        return response


def main(args: list[str] | None = None) -> int:
    with ros_session(args) as stop:
        node = SynchronousSlamToolbox()
        spin_until_stopped(node, stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
