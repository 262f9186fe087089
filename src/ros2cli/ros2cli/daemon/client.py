"""The CLI's side of the daemon: ask it, start it when absent, replace it when outdated.

Imports neither rclpy nor anything else heavy: with a running daemon a graph verb costs a
Python start and one Unix socket round trip.
"""

from __future__ import annotations

import fcntl
import socket
import sys
import time
from pathlib import Path
from typing import Any

from ros2cli.daemon import protocol
from ros2cli.verb_context import CliError

START_BOUND = 15.0     # from spawning to accepting connections (the import of rclpy is most)
ANSWER_BOUND = 30.0    # a fresh daemon answers once discovery has settled (a few seconds)


class NotRunning(Exception):
    """No daemon accepts connections for these settings."""


def _exchange(path: Path, message: dict[str, Any], timeout: float) -> dict[str, Any]:
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as sock:
        sock.settimeout(timeout)
        try:
            sock.connect(str(path))
        except (FileNotFoundError, ConnectionRefusedError) as error:
            raise NotRunning(str(error)) from None
        try:
            sock.sendall(protocol.encode(message))
            chunks = []
            while not chunks or not chunks[-1].endswith(b'\n'):
                chunk = sock.recv(1 << 16)
                if not chunk:
                    break
                chunks.append(chunk)
        except TimeoutError:
            raise CliError(f'The ros2 daemon did not answer within {timeout:g} s (stop it with '
                           '`ros2 daemon stop`, or use --no-daemon)') from None
        except OSError as error:
            raise _died(path, error) from None
    if not chunks:
        raise _died(path, None)
    try:
        return protocol.decode(b''.join(chunks))
    except protocol.ProtocolError:
        raise _died(path, None) from None


def _died(path: Path, error: OSError | None) -> CliError:
    # A daemon that rcl ended as it started (RMW_IMPLEMENTATION naming an RMW that is not
    # installed: "Expected RMW implementation identifier of ..., exiting with 102.") left
    # rcl's one line in its log: that line is the reason, and running again will not help.
    rcl_error = _last_rcl_error(_log_path(path))
    if rcl_error:
        return CliError(rcl_error)
    reason = f' ({error.strerror})' if error is not None and error.strerror else ''
    return CliError(f'The ros2 daemon stopped while answering{reason}; run the command again '
                    'to restart it')


def _last_rcl_error(log: Path) -> str | None:
    try:
        lines = [line for line in log.read_text(errors='replace').splitlines() if line.strip()]
    except OSError:
        return None
    last = lines[-1] if lines else ''
    return last if last.startswith('[ERROR] [') and '] [rcl]: ' in last else None


def socket_path() -> Path:
    """This shell's daemon socket; CliError (one line) when its directory is not private."""
    try:
        return protocol.socket_path()
    except OSError as error:
        raise CliError(f'Cannot use the ros2 daemon: {error}') from None


def request(message: dict[str, Any]) -> dict[str, Any]:
    """Ask the daemon, starting it (or replacing one of another version) as needed."""
    path = socket_path()
    message = {**message, 'version': protocol.version()}
    for _ in range(3):
        try:
            reply = _exchange(path, message, ANSWER_BOUND)
        except NotRunning:
            start(path)
            continue
        if reply.get('error') == 'version':
            stop(path)
            continue
        if not reply.get('ok'):
            raise CliError(f'The ros2 daemon failed: {reply.get("error")}')
        return reply
    raise CliError(f'Could not reach the ros2 daemon at {path} (see {_log_path(path)})')


def _log_path(path: Path) -> Path:
    return path.with_suffix('.log')


def is_running(path: Path | None = None) -> bool:
    try:
        return bool(_exchange(path or socket_path(), {'op': 'hello'}, 5.0).get('ok'))
    except NotRunning:
        return False


def start(path: Path | None = None) -> bool:
    """Start a detached daemon unless one answers; True when this call started it.

    Concurrent callers queue on a spawn lock, so 20 commands at once start one daemon.
    """
    path = path or socket_path()
    with open(path.with_suffix('.spawn'), 'a') as spawn_lock:
        fcntl.flock(spawn_lock, fcntl.LOCK_EX)
        if is_running(path):
            return False
        import subprocess
        with open(_log_path(path), 'wb') as log:
            process = subprocess.Popen(
                [sys.executable, '-m', 'ros2cli.daemon.server'], cwd='/',
                env=protocol.spawn_environment(), stdin=subprocess.DEVNULL, stdout=log,
                stderr=subprocess.STDOUT, start_new_session=True, close_fds=True)
        deadline = time.monotonic() + START_BOUND
        while not is_running(path):
            if process.poll() is not None and not _locked(path):
                raise CliError(f'The ros2 daemon could not start (see {_log_path(path)})')
            if time.monotonic() > deadline:
                raise CliError(f'The ros2 daemon did not start within {START_BOUND:g} s '
                               f'(see {_log_path(path)})')
            time.sleep(0.02)
        return True


def _locked(path: Path) -> bool:
    """Whether a daemon process (running or starting) holds the lock of these settings."""
    try:
        with open(protocol.lock_path(path), 'a') as lock:
            try:
                fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except BlockingIOError:
                return True
            return False
    except OSError:
        return False


def stop(path: Path | None = None, timeout: float = 10.0) -> bool:
    """Stop the daemon of these settings; True when one was running. Waits until it is gone."""
    path = path or socket_path()
    try:
        reply = _exchange(path, {'op': 'stop'}, 5.0)
    except NotRunning:
        return False
    except CliError:  # it went away before its answer reached us: stopped all the same
        reply = {'ok': True}
    deadline = time.monotonic() + timeout
    while _locked(path) and time.monotonic() < deadline:
        time.sleep(0.02)
    return bool(reply.get('ok'))
