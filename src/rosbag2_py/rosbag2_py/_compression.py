"""rosbag2's compression threads: what --compression-threads/-queue-size/-threads-priority set.

`threads` workers (0: one per CPU core), each at the nice value `priority`, take work from two
queues: messages to compress (MESSAGE mode) and closed storage files (FILE mode: a file is
compressed as soon as a split closes it, while recording goes on). Compressed messages are
handed back (take_compressed) for the writer's own thread to store: an SQLite3 connection
may only be used by the thread that opened it. As rosbag2's
SequentialCompressionWriter, a message queue longer than `queue_size` drops its oldest
messages; with `queue_size` 0 nothing is dropped and the writer waits while more than
`threads` messages are queued.
"""

from __future__ import annotations

import collections
import os
import threading
from collections.abc import Callable
from typing import Any


def compress_file(path: str) -> None:
    """`path` replaced by `path.zstd`, as rosbag2's file compression leaves it."""
    import zstandard

    with open(path, 'rb') as source, open(path + '.zstd', 'wb') as target:
        zstandard.ZstdCompressor().copy_stream(source, target)
    os.remove(path)


class CompressionPool:
    def __init__(self, threads: int, queue_size: int, priority: int) -> None:
        self.threads = threads if threads > 0 else (os.cpu_count() or 1)
        self.queue_size = max(0, queue_size)
        self.priority = priority
        self.dropped = 0
        self._done: collections.deque[tuple[Any, ...]] = collections.deque()
        self._messages: collections.deque[tuple[Any, ...]] = collections.deque()
        self._files: collections.deque[Callable[[], None]] = collections.deque()
        self._condition = threading.Condition()
        self._running = True
        self._errors: list[Exception] = []
        self._workers = [threading.Thread(target=self._work, name='rosbag2_compression',
                                          daemon=True) for _ in range(self.threads)]
        for worker in self._workers:
            worker.start()

    def put_message(self, topic: str, data: bytes, *rest: Any) -> None:
        with self._condition:
            if self.queue_size:
                while len(self._messages) > self.queue_size:
                    self._messages.popleft()
                    self.dropped += 1
            else:
                self._condition.wait_for(
                    lambda: len(self._messages) <= self.threads or self._errors)
            self._messages.append((topic, data, *rest))
            self._condition.notify_all()

    def put_file(self, work: Callable[[], None]) -> None:
        with self._condition:
            self._files.append(work)
            self._condition.notify_all()

    def _work(self) -> None:
        import zstandard

        if self.priority:
            try:
                os.setpriority(os.PRIO_PROCESS, threading.get_native_id(), self.priority)
            except OSError as error:  # e.g. a negative nice value without the right
                self._errors.append(error)
                return
        compressor = zstandard.ZstdCompressor()  # one per thread: contexts are not shared
        while True:
            with self._condition:
                self._condition.wait_for(
                    lambda: self._messages or self._files or not self._running)
                message = self._messages.popleft() if self._messages else None
                work = self._files.popleft() if message is None and self._files else None
                self._condition.notify_all()
                if message is None and work is None:
                    return  # stopped, nothing left
            try:
                if message is not None:
                    topic, data, *rest = message
                    self._done.append((topic, compressor.compress(data), *rest))
                elif work is not None:
                    work()
            except Exception as error:  # surfaced by close(): the writer names it
                with self._condition:
                    self._errors.append(error)
                    self._condition.notify_all()

    def take_compressed(self) -> list[tuple[Any, ...]]:
        """The messages compressed so far (topic, data, ...), each handed out once."""
        taken = []
        while self._done:
            taken.append(self._done.popleft())
        return taken

    def close(self) -> None:
        """Finish what is queued, end the threads; the first failure is raised here."""
        with self._condition:
            self._running = False
            self._condition.notify_all()
        for worker in self._workers:
            worker.join()
        if self._errors:
            raise self._errors[0]
