"""ReadyAggregator: calls ready_fn once its own ready_fn was called n times."""

from __future__ import annotations

import threading
from collections.abc import Callable


class ReadyAggregator:
    def __init__(self, ready_fn: Callable[[], None], num_to_aggregate: int) -> None:
        self._parent_ready_fn = ready_fn
        self._remaining = num_to_aggregate
        self._lock = threading.Lock()

    def ready_fn(self) -> None:
        with self._lock:
            self._remaining -= 1
            remaining = self._remaining
        if remaining == 0:  # called outside the lock: the parent may take locks of its own
            self._parent_ready_fn()
