"""Snapshot mode (StorageOptions.snapshot_mode, `ros2 bag record --snapshot-mode`).

Messages are not written as they come but kept in memory, the newest ones up to
`max_cache_size` bytes of message data (rosbag2's CircularMessageCache); a snapshot
(`take_snapshot()`, the recorder's `~/snapshot` service) writes what the buffer holds to the
bag and starts it afresh. What is left in the buffer when recording ends is not written.
"""

from __future__ import annotations

import threading
from collections import deque
from typing import Any

# Jazzy's own words (rosbag2_cpp's SequentialWriter::open and the circular buffer).
NO_CACHE = 'Max cache size must be greater than 0 when snapshot mode is enabled'
TOO_BIG = 'Last message exceeds snapshot buffer size. Dropping message!'


def check_snapshot_options(storage_options: Any) -> None:
    """RuntimeError with Jazzy's message when snapshot mode has no cache to keep messages in."""
    if storage_options.snapshot_mode and not storage_options.max_cache_size > 0:
        raise RuntimeError(NO_CACHE)


class SnapshotBuffer:
    """The newest messages, `(topic, data, ...)` tuples, up to `max_bytes` bytes of data."""

    def __init__(self, max_bytes: int) -> None:
        self.max_bytes = int(max_bytes)
        self._messages: deque[tuple] = deque()
        self._bytes = 0
        self._lock = threading.Lock()  # a writer may be written from several threads

    def push(self, message: tuple) -> bool:
        """Keep `message`, dropping the oldest ones to make room; False if it cannot fit."""
        size = len(message[1])
        if size > self.max_bytes:
            from rclpy.logging import get_logger
            get_logger('rosbag2_cpp').warning(TOO_BIG)
            return False
        with self._lock:
            while self._messages and self._bytes + size > self.max_bytes:
                self._bytes -= len(self._messages.popleft()[1])
            self._messages.append(message)
            self._bytes += size
        return True

    def take(self) -> list[tuple]:
        """Everything held, oldest first; the buffer is empty afterwards."""
        with self._lock:
            taken, self._messages, self._bytes = list(self._messages), deque(), 0
        return taken
