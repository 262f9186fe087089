"""The canvas for other processes: hidden topic `~/_canvas`, published only while watched.

Each message is a std_msgs/UInt8MultiArray holding one PNG of the composited canvas
(background, trails, turtles); `layout.dim[0].label` reads `image/png stamp=<ns>` with the
wall-clock time the image was taken. A thread checks for subscribers; with none it costs a
count query every 0.2 s. With some, it sends a frame when something visible changed (at most
FPS per second) and at least one every KEYFRAME_PERIOD (a `clear` changes no turtle).
The topic is hidden (leading `_`), so `ros2 topic list` matches upstream turtlesim.
"""

from __future__ import annotations

import os
import threading
import time
from array import array
from typing import TYPE_CHECKING

from PySide6.QtCore import QBuffer, QByteArray, QIODevice
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from std_msgs.msg import MultiArrayDimension, UInt8MultiArray

if TYPE_CHECKING:
    from turtlesim_py.frame import TurtleFrame

FPS = 40.0  # the tick runs at 62.5 Hz; the page needs >= 30 frames/s
IDLE_CHECK_PERIOD = 0.2  # seconds between subscriber checks while nobody watches
KEYFRAME_PERIOD = 0.5
PNG_QUALITY = 80  # Qt's PNG "quality": higher is less zlib effort (faster, bigger)
QOS = QoSProfile(depth=1, history=HistoryPolicy.KEEP_LAST,
                 reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.VOLATILE)


class CanvasStream:
    def __init__(self, frame: TurtleFrame) -> None:
        self.frame = frame
        self.publisher = frame.create_publisher(UInt8MultiArray, '~/_canvas', QOS)
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    def start(self) -> None:
        self._thread = threading.Thread(target=self._run, name='turtlesim-canvas-stream',
                                        daemon=True)
        self._thread.start()

    def stop(self) -> None:
        self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout=2.0)

    def _run(self) -> None:
        if os.environ.get('QT_QPA_PLATFORM') == 'offscreen':
            self.frame.get_logger().info(live_view_hint())
        last_state = None
        last_sent = 0.0
        while not self._stop.is_set():
            try:
                watched = self.publisher.get_subscription_count() > 0
            except Exception:  # the node is being destroyed
                return
            if not watched:
                last_state = None
                self._stop.wait(IDLE_CHECK_PERIOD)
                continue
            started = time.monotonic()
            with self.frame.lock:
                state = (self.frame.background(), tuple(t.sprite() for t in self.frame._order))
            if state != last_state or started - last_sent >= KEYFRAME_PERIOD:
                self._publish()
                last_state, last_sent = state, started
            self._stop.wait(max(0.001, 1.0 / FPS - (time.monotonic() - started)))

    def _publish(self) -> None:
        stamp = time.time_ns()
        image = self.frame.composite()
        data = QByteArray()
        buffer = QBuffer(data)
        buffer.open(QIODevice.OpenModeFlag.WriteOnly)
        image.save(buffer, 'PNG', PNG_QUALITY)
        msg = UInt8MultiArray()
        png = data.data()
        msg.layout.dim = [MultiArrayDimension(label=f'image/png stamp={stamp}', size=len(png),
                                              stride=len(png))]
        msg.data = array('B', png)  # the setter's fast path (bytes get checked one by one)
        self.publisher.publish(msg)


# Viewers register a function in this entry-point group that returns the URL where a
# headless turtlesim can be watched now, or None (rqt_web: its Turtlesim page). turtlesim
# looks them up instead of importing a viewer: the simulator knows no viewer package.
LIVE_VIEW_GROUP = 'turtlesim.live_view'


def live_view_hint() -> str:
    """Where a headless turtlesim can be watched: a registered viewer's URL when one runs."""
    from importlib.metadata import entry_points
    for entry_point in sorted(entry_points(group=LIVE_VIEW_GROUP), key=lambda e: e.name):
        try:
            url = entry_point.load()()
        except Exception:  # a viewer not importable, or its state unreadable: just the hint
            url = None
        if url:
            return f'Live view: {url}'
    return 'Headless: watch the canvas live in a browser with `rqt turtlesim`'
