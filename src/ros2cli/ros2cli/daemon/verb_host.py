"""The daemon's side of a one-shot verb run for the CLI (`topic echo --once`, `param get`, ...).

A verb with a node of its own used to create a DDS participant and wait for discovery: 0.3 to
2 s, depending on when the other participants' announcements arrive. The daemon's participant
met the graph long ago, so a verb that does one thing and exits (its module says which runs
with `runs_in_daemon(args)`) runs there, in a thread. The CLI has parsed the command line: it
sends the verb's module, its main and the parsed arguments, and the daemon calls
main(args, context) with a VerbContext whose streams write to the CLI's terminal (as they are
written), whose rclpy context is the daemon's (its node is a node of the daemon's participant,
whose endpoints the other nodes match within milliseconds), and whose `cancelled` is set when
the CLI goes away (Ctrl-C).

A CLI in another environment (a sourced overlay: other interfaces, other code) is served by
the daemon's worker for that environment (server.py), a process started with the CLI's own
interpreter and variables. The CLI runs the verb itself whenever neither can: none running
or not ready yet, or interface code loaded that has changed on disk since (a rebuilt
package): no answer from stale code. The CLI's side is verb_client.py.
"""

from __future__ import annotations

import argparse
import importlib
import io
import os
import sys
import threading
from collections.abc import Callable
from typing import Any

from ros2cli.verb_context import VerbContext, run_main


class CliStream(io.TextIOBase):
    """One of the CLI's terminal streams (`out` or `err`), seen from the daemon: each write is
    sent to the CLI at once."""

    def __init__(self, send: Callable[[str, str], None], kind: str) -> None:
        self._send = send
        self._kind = kind

    def writable(self) -> bool:
        return True

    def write(self, text: str) -> int:
        self._send(self._kind, text)
        return len(text)

    def isatty(self) -> bool:
        return False


def run(request: dict[str, Any], ros_context: Any, send: Callable[[str, str], None],
        cancelled: threading.Event) -> int:
    """Run the verb the CLI parsed (`module`, `main`, `args` of the request) in this thread."""
    context = VerbContext(CliStream(send, 'out'), CliStream(send, 'err'),
                          int(request.get('pid', 0)), ros_context, cancelled)
    try:
        func = getattr(importlib.import_module(str(request['module'])), str(request['main']))
        args = argparse.Namespace(**request['args'])
    except (KeyError, TypeError, ImportError, AttributeError) as error:
        print(f'The ros2 daemon cannot run this verb: {error}', file=context.stderr)
        return 1
    try:
        return run_main(func, args, context)
    except KeyboardInterrupt:  # the CLI went away
        return 2


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
