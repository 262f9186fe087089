"""The daemon's workers: one process per other environment of the CLIs it serves.

A CLI whose environment (protocol.ENVIRONMENT: a sourced overlay) is not the daemon's cannot
have its verb run in the daemon's process, which has loaded other code and interfaces. The
daemon starts `python -m ros2cli.daemon.server --worker` with that CLI's interpreter and
variables; it serves verbs for that environment on its own socket (protocol.worker_path)
once it has met the graph. A worker ends when its stdin closes (the daemon stopped or died),
or by itself when its code is outdated; the next CLI of that environment starts a new one.
"""

from __future__ import annotations

import subprocess
import sys
import threading
import time
from pathlib import Path
from typing import Any

from ros2cli.daemon import protocol

MAX_WORKERS = 8        # environments served at once; a CLI beyond them runs its verb itself
STOP_BOUND = 5.0       # seconds the daemon waits for its workers when it stops


class Workers:
    def __init__(self, daemon_socket: Path) -> None:
        self._socket = daemon_socket
        self._running: dict[Path, subprocess.Popen[bytes]] = {}
        self._lock = threading.Lock()

    def for_cli(self, request: dict[str, Any]) -> Path | None:
        """The socket of the worker for the requesting CLI's environment, started now if none
        runs (it serves from a later request on); None when there is none to ask."""
        executable, env = request.get('executable'), request.get('env')
        values = request.get('environment')
        if not isinstance(executable, str) or not isinstance(env, dict) \
                or not isinstance(values, dict):
            return None
        path = protocol.worker_path(self._socket, {str(k): str(v) for k, v in values.items()})
        with self._lock:
            for known, process in list(self._running.items()):
                if process.poll() is not None:  # outdated or idle: it left
                    del self._running[known]
            if path in self._running:
                return path
            if len(self._running) >= MAX_WORKERS:
                return None
            try:
                with open(path.with_suffix('.log'), 'wb') as log:
                    self._running[path] = subprocess.Popen(
                        [executable, '-m', 'ros2cli.daemon.server', '--worker'], cwd='/',
                        env={str(k): str(v) for k, v in env.items()}, stdin=subprocess.PIPE,
                        stdout=log, stderr=subprocess.STDOUT, start_new_session=True,
                        close_fds=True)
            except (OSError, ValueError) as error:  # e.g. that interpreter is gone
                print(f'cannot start a worker for {path.name}: {error}', file=sys.stderr,
                      flush=True)
                return None
            print(f'started worker {self._running[path].pid} for {path.name}',
                  file=sys.stderr, flush=True)
        return path

    def stop(self) -> None:
        """Close the workers' stdin (they stop on that) and wait for them, bounded."""
        with self._lock:
            workers, self._running = list(self._running.values()), {}
        for process in workers:
            try:
                process.stdin.close()
            except OSError:
                pass
        deadline = time.monotonic() + STOP_BOUND
        for process in workers:
            try:
                process.wait(timeout=max(0.1, deadline - time.monotonic()))
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()


def exit_with_daemon(shutdown: Any) -> None:
    """In a worker: the daemon holds our stdin; end of file means it has gone."""
    try:
        while sys.stdin.buffer.read(1 << 12):
            pass
    except OSError:
        pass
    shutdown()
