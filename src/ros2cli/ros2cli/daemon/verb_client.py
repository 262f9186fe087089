"""The CLI's side of a one-shot verb run by the daemon: send the parsed verb, show its output.

The daemon (server.py) runs the verb when its environment is the CLI's, else hands it to its
worker for the CLI's environment (a sourced overlay): the answer then names the worker's
socket, and the CLI asks there. Whoever cannot run it declines before the verb starts, and
the CLI runs the verb itself (cli.py). The daemon's side is verb_host.py. Imports nothing heavy.
"""

from __future__ import annotations

import argparse
import os
import socket
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

from ros2cli.daemon import protocol


def run_in_daemon(func: Callable[..., Any], args: argparse.Namespace) -> int | None:
    """The exit code of the verb `func` (a verb module's main) run with the parsed `args` by
    this shell's daemon or its worker; None when the CLI must run it (no daemon, not ready,
    another version, stale code, a worker still starting, arguments that are not plain data)."""
    try:
        path = protocol.socket_path()
    except OSError:
        return None
    values = {name: value for name, value in vars(args).items() if not name.startswith('_')}
    request = {'op': 'run', 'module': func.__module__, 'main': func.__name__, 'args': values,
               'pid': os.getpid(), 'environment': protocol.environment(),
               'version': protocol.version(),
               # For a worker the daemon starts: this process's interpreter and variables.
               'executable': sys.executable, 'env': dict(os.environ)}
    try:
        protocol.encode(request)
    except (TypeError, ValueError):  # e.g. an open file: only this process can use it
        return None
    outcome = _run(path, request)
    if isinstance(outcome, dict) and outcome.get('worker'):
        outcome = _run(Path(outcome['worker']), request)
    return outcome if isinstance(outcome, int) else None


def _run(path: Path, request: dict[str, Any]) -> int | dict[str, Any] | None:
    """The exit code; the decline message; None when nobody listens at `path`."""
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as sock:
        try:
            sock.connect(str(path))
            sock.sendall(protocol.encode(request))
        except OSError:
            return None  # no daemon (graph verbs start it): run here
        return _stream(sock)


def _stream(sock: socket.socket) -> int | dict[str, Any] | None:
    written = interrupted = False
    lines = sock.makefile('rb')
    while True:
        try:
            line = lines.readline()
        except KeyboardInterrupt:
            if interrupted:  # a second Ctrl-C: leave at once
                raise
            # Ctrl-C: the daemon ends the verb as Ctrl-C would (send_goal cancels its goal,
            # ...), and what the verb says meanwhile is still shown.
            sock.shutdown(socket.SHUT_WR)
            interrupted = True
            continue
        try:
            message = protocol.decode(line)
        except protocol.ProtocolError:
            break  # end of stream: the daemon died
        if 'exit' in message:
            return int(message['exit'])
        if 'declined' in message:  # before the verb started
            return message
        stream = sys.stdout if 'out' in message else sys.stderr
        try:
            stream.write(message.get('out', message.get('err', '')))
            stream.flush()
        except BrokenPipeError:
            # The reader went away (`ros2 ... | head`): stop quietly, as cli._guard does.
            os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
            return 1
        written = True
    if not written:
        return None
    print('The ros2 daemon stopped while running the command; run it again', file=sys.stderr)
    return 1
