"""The foxglove-sdk server's own log lines, through the bridge's ROS logger, once per client.

The SDK (Rust) logs through Python's `logging` under the `foxglove` logger; with no handler
configured, Python printed its records bare on stderr. A client that leaves with data still in
flight can make it log one line per queued message ('Error sending message to client A:
Broken pipe', about 510 lines for one closed Lichtblick tab): after the first line that names
a client, further lines naming the same client are dropped for a while.
"""

from __future__ import annotations

import logging
import re
import time
from typing import Any

CLIENT = re.compile(r'\bclient (\S+:\d+)')
QUIET_FOR = 60.0  # seconds a client's further lines are dropped after its first one
REMEMBERED = 1024  # clients remembered at most (oldest forgotten first)


class OncePerClient(logging.Handler):
    def __init__(self, ros_logger: Any) -> None:
        super().__init__()
        self._ros_logger = ros_logger
        self._seen: dict[str, float] = {}

    def first_for_client(self, message: str) -> bool:
        match = CLIENT.search(message)
        if match is None:
            return True
        now = time.monotonic()
        last = self._seen.get(match.group(1))
        if last is not None and now - last < QUIET_FOR:
            return False
        self._seen.pop(match.group(1), None)
        self._seen[match.group(1)] = now
        while len(self._seen) > REMEMBERED:
            del self._seen[next(iter(self._seen))]
        return True

    def emit(self, record: logging.LogRecord) -> None:
        try:
            message = record.getMessage()
            if not self.first_for_client(message):
                return
            if record.levelno >= logging.ERROR:
                self._ros_logger.error(message)
            elif record.levelno >= logging.WARNING:
                self._ros_logger.warn(message)
            elif record.levelno >= logging.INFO:
                self._ros_logger.info(message)
            else:
                self._ros_logger.debug(message)
        except Exception:  # a log line must never take the SDK's thread down
            self.handleError(record)


def route_sdk_logs(ros_logger: Any) -> OncePerClient:
    """Send the SDK's records (WARNING and up, as Python printed them before) to `ros_logger`."""
    handler = OncePerClient(ros_logger)
    sdk = logging.getLogger('foxglove')
    sdk.addHandler(handler)
    sdk.setLevel(logging.WARNING)
    sdk.propagate = False
    return handler
