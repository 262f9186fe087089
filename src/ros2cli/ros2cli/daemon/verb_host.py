"""The daemon's side of a one-shot verb run for the CLI (`topic echo --once`, `param get`, ...).

A verb with a node of its own used to create a DDS participant and wait for discovery: 0.3 to
2 s, depending on when the other participants' announcements arrive. The daemon's participant
met the graph long ago, so a verb that does one thing and exits (its module says which runs
with `runs_in_daemon(args)`) runs there, in a thread. Its node is made in the daemon's
context (the same participant, whose endpoints the other nodes match within milliseconds),
its stdout and stderr stream back to the CLI as they are written, and it stops when the CLI
goes away (Ctrl-C).

A CLI in another environment (a sourced overlay: other interfaces, other code) is served by
the daemon's worker for that environment (server.py), a process started with the CLI's own
interpreter and variables. The CLI runs the verb itself whenever neither can: none running
or not ready yet, or interface code loaded that has changed on disk since (a rebuilt
package): no answer from stale code. The CLI's side is verb_client.py.
"""

from __future__ import annotations

import io
import os
import sys
import threading
from collections.abc import Callable
from typing import Any

_local = threading.local()


class Session:
    """The verb running in this thread: its CLI's pid, the daemon's context, its output."""

    def __init__(self, context: Any, pid: int, send: Callable[[str, str], None],
                 cancelled: threading.Event) -> None:
        self.context = context
        self.pid = pid
        self.send = send
        self.cancelled = cancelled
        self._interrupted = False

    def take_interrupt(self) -> bool:
        """True once after the CLI has left or pressed Ctrl-C: the verb then gets one
        KeyboardInterrupt, as from one SIGINT (send_goal still waits for its cancel)."""
        if self.cancelled.is_set() and not self._interrupted:
            self._interrupted = True
            return True
        return False


def session() -> Session | None:
    """The daemon's session of the verb this thread runs; None in the CLI (and elsewhere)."""
    return getattr(_local, 'session', None)


class _ThreadStream(io.TextIOBase):
    """The daemon's sys.stdout/stderr: a verb thread writes to its CLI, others to the log."""

    def __init__(self, log: Any, kind: str) -> None:
        self._log = log
        self._kind = kind

    def write(self, text: str) -> int:
        current = session()
        if current is None:
            return self._log.write(text)
        current.send(self._kind, text)
        return len(text)

    def flush(self) -> None:
        if session() is None:
            self._log.flush()

    def isatty(self) -> bool:
        return False


def install_streams() -> None:
    sys.stdout = _ThreadStream(sys.stdout, 'out')
    sys.stderr = _ThreadStream(sys.stderr, 'err')


def run(argv: list[str], current: Session) -> int:
    """Parse and run the verb as `ros2` would, in this thread, for `current`'s CLI."""
    from ros2cli import cli
    _local.session = current
    try:
        result = cli.run_here(argv)
    except SystemExit as done:  # argparse: --help, a bad argument
        result = done.code if isinstance(done.code, int) else (0 if done.code is None else 1)
    except KeyboardInterrupt:  # the CLI went away
        result = 2
    finally:
        _local.session = None
    return result if isinstance(result, int) else 1


class LoadedCode:
    """Interface and package modules the daemon has loaded from the workspace's prefixes and
    PYTHONPATH, with their files' stamps: once one changed on disk (a rebuild), the daemon's
    copy is stale."""

    def __init__(self) -> None:
        self._stamps: dict[str, tuple[int, int]] = {}

    def changed(self) -> bool:
        paths = (os.environ.get('AMENT_PREFIX_PATH', '').split(os.pathsep)
                 + os.environ.get('PYTHONPATH', '').split(os.pathsep))
        prefixes = tuple(p.rstrip('/') + '/' for p in paths if p)
        for module in list(sys.modules.values()):
            path = getattr(module, '__file__', None)
            if not path or not path.startswith(prefixes):
                continue
            try:
                info = os.stat(path)
            except OSError:
                return True
            stamp = (info.st_mtime_ns, info.st_size)
            if self._stamps.setdefault(path, stamp) != stamp:
                return True
        return False
