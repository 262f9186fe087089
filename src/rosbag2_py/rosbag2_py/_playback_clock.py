"""The player's clock: bag time against the steady clock, with a rate, pauses and jumps
(what rosbag2's TimeControllerClock does for Jazzy's player)."""

from __future__ import annotations

import threading
import time
from collections.abc import Callable

WAKE_PERIOD = 0.1  # seconds: the longest a sleep goes without looking at `interrupt`


class PlaybackClock:
    def __init__(self, start_ns: int, rate: float, paused: bool) -> None:
        self._condition = threading.Condition()
        self.rate = rate
        self.paused = paused
        self._anchor_bag = start_ns
        self._anchor_steady = time.monotonic()

    def _now(self) -> int:
        if self.paused:
            return self._anchor_bag
        return self._anchor_bag + int((time.monotonic() - self._anchor_steady) * self.rate * 1e9)

    def _anchor(self, bag_ns: int) -> None:
        self._anchor_bag = bag_ns
        self._anchor_steady = time.monotonic()
        self._condition.notify_all()

    def now(self) -> int:
        """Bag time (ns): it stands still while paused."""
        with self._condition:
            return self._now()

    def jump(self, bag_ns: int) -> None:
        with self._condition:
            self._anchor(bag_ns)

    def pause(self) -> bool:
        """False if already paused."""
        with self._condition:
            if self.paused:
                return False
            self._anchor(self._now())
            self.paused = True
            return True

    def resume(self) -> bool:
        """False if not paused."""
        with self._condition:
            if not self.paused:
                return False
            self.paused = False
            self._anchor(self._anchor_bag)
            return True

    def set_rate(self, rate: float) -> bool:
        """False (rate unchanged) unless `rate` > 0."""
        if not rate > 0.0:
            return False
        with self._condition:
            self._anchor(self._now())
            self.rate = rate
            return True

    def wake(self) -> None:
        with self._condition:
            self._condition.notify_all()

    def sleep_until(self, bag_ns: int, interrupt: Callable[[], bool]) -> bool:
        """True once bag time reaches `bag_ns`; False as soon as `interrupt()` holds (looked
        at on every change of the clock, wake(), and every WAKE_PERIOD)."""
        with self._condition:
            while not interrupt():
                if self.paused:
                    remaining = WAKE_PERIOD
                else:
                    remaining = (bag_ns - self._now()) / self.rate / 1e9
                    if remaining <= 0:
                        return True
                self._condition.wait(min(remaining, WAKE_PERIOD))
            return False
