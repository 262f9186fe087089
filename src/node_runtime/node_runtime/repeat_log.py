"""Repeated log lines, rate-limited: the first at once, then at most one per period.

A turtle fed NaN cmd_vel at 62 Hz used to log the same ERROR 62 times a second, drowning
every other line. Here a repeat of the same cause from the same source (the caller's key) is
counted instead, and the next line that gets through says how many were suppressed.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Hashable

PERIOD = 1.0  # seconds between two lines of the same key
_MAX_KEYS = 4096  # keys are per turtle and field: bound the table anyway


class RepeatLimiter:
    """Decide, per key, whether a line is logged now and with how many suppressed before it."""

    def __init__(self, period: float = PERIOD,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self.period = period
        self._clock = clock
        self._seen: dict[Hashable, list] = {}  # key -> [time of the last line, suppressed]

    def admit(self, key: Hashable) -> int | None:
        """None to stay quiet; otherwise the number of repeats suppressed since the last line."""
        now = self._clock()
        entry = self._seen.get(key)
        if entry is None:
            if len(self._seen) >= _MAX_KEYS:
                self._seen.clear()
            self._seen[key] = [now, 0]
            return 0
        if now - entry[0] < self.period:
            entry[1] += 1
            return None
        suppressed = entry[1]
        entry[0], entry[1] = now, 0
        return suppressed


def with_count(message: str, suppressed: int) -> str:
    if not suppressed:
        return message
    return f'{message} ({suppressed} repeats suppressed since the last report)'


class RepeatedLog:
    """A logger front for per-message/per-tick errors: `log.error(key, message)`."""

    def __init__(self, logger, period: float = PERIOD,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self._logger = logger
        self._limiter = RepeatLimiter(period, clock)

    def error(self, key: Hashable, message: str) -> None:
        suppressed = self._limiter.admit(key)
        if suppressed is not None:
            self._logger.error(with_count(message, suppressed))
