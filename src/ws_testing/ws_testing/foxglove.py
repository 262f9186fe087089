"""A foxglove WebSocket client for the foxglove_bridge tests: @foxglove/ws-protocol's client
(npm, pinned by tests/foxglove_client/package-lock.json; scripts/test runs `npm ci`) driven
through tests/foxglove_client/driver.mjs."""

from __future__ import annotations

import json
import queue
import shutil
import subprocess
import threading
import time
from collections.abc import Callable
from typing import Any

import pytest

from ws_testing.support import REPO

CLIENT_DIR = REPO / 'tests' / 'foxglove_client'

# pytestmark of the tests that drive a client.
needs_client = pytest.mark.skipif(
    shutil.which('node') is None or not (CLIENT_DIR / 'node_modules').is_dir(),
    reason='needs node and tests/foxglove_client/node_modules (scripts/test runs npm ci)')


class Driver:
    """driver.mjs as a child process: JSON commands in, JSON events out."""

    def __init__(self, url: str, subprotocol: str) -> None:
        self.popen = subprocess.Popen(
            ['node', str(CLIENT_DIR / 'driver.mjs'), url, subprotocol], stdin=subprocess.PIPE,
            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, bufsize=1)
        self.events: list[dict[str, Any]] = []
        self._lines: queue.Queue[str] = queue.Queue()
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self) -> None:
        for line in self.popen.stdout:
            try:
                self.events.append(json.loads(line))
            except ValueError:
                self.events.append({'event': 'stray', 'text': line})

    def send(self, op: str, **fields: Any) -> dict[str, Any]:
        count = len(self.events)
        self.popen.stdin.write(json.dumps({'op': op, **fields}) + '\n')
        self.popen.stdin.flush()
        return self.wait(lambda e: e.get('command') == op, f'the answer to {op}', since=count)

    def wait(self, predicate: Callable[[dict[str, Any]], bool], what: str,
             timeout: float = 10.0, since: int = 0) -> dict[str, Any]:
        deadline = time.monotonic() + timeout
        while True:
            for event in self.events[since:]:
                if predicate(event):
                    if event.get('event') == 'failed':
                        raise AssertionError(f'driver failed: {event}')
                    return event
            if time.monotonic() > deadline:
                raise AssertionError(f'timed out after {timeout} s waiting for {what}; '
                                     f'events: {self.summary()}')
            time.sleep(0.02)

    def summary(self) -> str:
        return '\n'.join(json.dumps(e)[:300] for e in self.events[-30:])

    def of(self, kind: str, since: int = 0) -> list[dict[str, Any]]:
        return [e for e in self.events[since:] if e.get('event') == kind]

    def close(self) -> None:
        if self.popen.poll() is None:
            self.popen.stdin.close()
            try:
                self.popen.wait(timeout=5)
            except subprocess.TimeoutExpired:
                self.popen.kill()
                self.popen.wait()
