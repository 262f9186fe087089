"""MessagePump: spins a node on a thread of its own, so tests need not spin it."""

from __future__ import annotations

import threading
from typing import Any


class MessagePump:
    def __init__(self, node: Any, context: Any = None) -> None:
        self._node = node
        self._context = context
        self._running = threading.Event()
        self._thread = threading.Thread(target=self._spin, name='msg_pump_thread', daemon=True)

    def start(self) -> None:
        self._running.set()
        self._thread.start()

    def stop(self) -> None:
        self._running.clear()
        self._thread.join(timeout=5.0)
        if self._thread.is_alive():
            raise Exception('Timed out waiting for message pump to stop')

    def _spin(self) -> None:
        from rclpy.executors import SingleThreadedExecutor
        executor = SingleThreadedExecutor(context=self._context)
        executor.add_node(self._node)
        try:
            while self._running.is_set():
                executor.spin_once(timeout_sec=0.1)
        finally:
            executor.remove_node(self._node)
