"""One rqt web app per user and ROS settings: where its state file lives, find it, start it.

The server writes a small JSON state file (mode 0600: it holds the token) once it listens;
the launchers read it, check the server answers, and start a detached server when none does.
A lock file keeps two launchers typed at the same time from starting two servers.
"""

from __future__ import annotations

import fcntl
import hashlib
import json
import os
import subprocess
import sys
import time
import urllib.error
import urllib.request
from dataclasses import dataclass
from pathlib import Path

from node_runtime.discovery import is_ours

# The environment that decides which ROS graph a server sees: a different value is another app.
ROS_SETTINGS = ('ROS_DOMAIN_ID', 'ROS_AUTOMATIC_DISCOVERY_RANGE', 'ROS_STATIC_PEERS',
                'ROS_LOCALHOST_ONLY', 'RMW_IMPLEMENTATION', 'FASTRTPS_DEFAULT_PROFILES_FILE',
                'ROS_SECURITY_ENABLE', 'ROS_SECURITY_KEYSTORE')
START_TIMEOUT = 20.0  # seconds for a new server to listen (rclpy import + DDS start)

PAGES = {
    'index': ('/', 'rqt'),
    'graph': ('/graph', 'Node Graph'),
    'services': ('/services', 'Service Caller'),
    'topics': ('/topics', 'Topics'),
    'parameters': ('/parameters', 'Parameters'),
    'console': ('/console', 'Console'),
    'actions': ('/actions', 'Actions'),
    'turtlesim': ('/turtlesim', 'Turtlesim'),
    'tf_tree': ('/tf_tree', 'TF Tree'),
    'foxglove': ('/foxglove', 'Foxglove'),
    'rviz': ('/rviz', 'RViz'),
    'joint_state_publisher': ('/joint_state_publisher', 'Joint State Publisher'),
}


@dataclass
class Instance:
    pid: int
    host: str
    port: int
    token: str

    def url(self, page: str = 'index') -> str:
        path = PAGES[page][0]
        host = '127.0.0.1' if self.host in ('0.0.0.0', '') else self.host
        if ':' in host:
            host = f'[{host}]'
        return f'http://{host}:{self.port}{path}?token={self.token}'


def state_dir() -> Path:
    """$RQT_WEB_STATE_DIR, else $XDG_RUNTIME_DIR/rqt_web, else ~/.cache/rqt_web (mode 0700)."""
    base = os.environ.get('RQT_WEB_STATE_DIR')
    if base:
        path = Path(base)
    elif os.environ.get('XDG_RUNTIME_DIR'):
        path = Path(os.environ['XDG_RUNTIME_DIR']) / 'rqt_web'
    else:
        path = Path.home() / '.cache' / 'rqt_web'
    path.mkdir(parents=True, exist_ok=True, mode=0o700)
    return path


def settings_key() -> str:
    """A short name for this user's ROS settings (and Python environment)."""
    settings = {name: os.environ.get(name, '') for name in ROS_SETTINGS}
    if is_ours(settings['FASTRTPS_DEFAULT_PROFILES_FILE']):
        # Set by our own nodes for themselves (node_runtime.discovery): not the user's choice.
        settings['FASTRTPS_DEFAULT_PROFILES_FILE'] = ''
    settings['prefix'] = sys.prefix
    digest = hashlib.sha256(json.dumps(settings, sort_keys=True).encode()).hexdigest()[:12]
    return f'domain{settings["ROS_DOMAIN_ID"] or 0}-{digest}'


def state_file() -> Path:
    return state_dir() / f'{settings_key()}.json'


def write_state(path: Path, instance: Instance) -> None:
    temporary = path.with_suffix('.tmp')
    fd = os.open(temporary, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
    with os.fdopen(fd, 'w') as handle:
        json.dump(instance.__dict__, handle)
    os.replace(temporary, path)


def read_state(path: Path | None = None) -> Instance | None:
    try:
        data = json.loads((path or state_file()).read_text())
        return Instance(int(data['pid']), str(data['host']), int(data['port']),
                        str(data['token']))
    except (OSError, ValueError, KeyError, TypeError):
        return None


def answers(instance: Instance, timeout: float = 2.0) -> bool:
    """Whether the server of `instance` is alive and is ours (it knows the token)."""
    try:
        os.kill(instance.pid, 0)
    except OSError:
        return False
    host = '127.0.0.1' if instance.host in ('0.0.0.0', '') else instance.host
    if ':' in host:
        host = f'[{host}]'
    request = urllib.request.Request(f'http://{host}:{instance.port}/api/ping',
                                     headers={'X-Rqt-Token': instance.token})
    try:
        with urllib.request.urlopen(request, timeout=timeout) as response:
            return response.status == 200
    except (urllib.error.URLError, OSError):
        return False


def running() -> Instance | None:
    """The server for the current ROS settings, when one is up and answering."""
    instance = read_state()
    return instance if instance is not None and answers(instance) else None


def turtlesim_live_view() -> str | None:
    """The Turtlesim page's URL when the app for these settings runs (entry point
    `turtlesim.live_view`: a headless turtlesim prints it)."""
    server = running()
    return server.url('turtlesim') if server is not None else None


def ensure_running(host: str = '127.0.0.1', port: int = 0) -> tuple[Instance, bool]:
    """(the server for these settings, whether it was started now); RuntimeError if it fails."""
    path = state_file()
    with open(path.with_suffix('.lock'), 'w') as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        instance = read_state(path)
        if instance is not None and answers(instance):
            return instance, False
        return _start(path, host, port), True


def _start(path: Path, host: str, port: int) -> Instance:
    log_path = path.with_suffix('.log')
    path.unlink(missing_ok=True)
    with open(log_path, 'wb') as log:
        process = subprocess.Popen(
            [sys.executable, '-m', 'rqt_web.server', '--state-file', str(path),
             '--host', host, '--port', str(port)],
            stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT,
            start_new_session=True, close_fds=True)
    deadline = time.monotonic() + START_TIMEOUT
    while time.monotonic() < deadline:
        if process.poll() is not None:
            break
        instance = read_state(path)
        if instance is not None and instance.pid == process.pid and answers(instance):
            return instance
        time.sleep(0.05)
    if process.poll() is None:
        process.kill()
    tail = log_path.read_text(errors='replace').strip().splitlines()[-5:]
    raise RuntimeError('the rqt web server did not start' +
                       (':\n  ' + '\n  '.join(tail) if tail else '') + f'\n(log: {log_path})')


def stop() -> bool:
    """Stop the server for the current ROS settings; whether one was running."""
    instance = read_state()
    if instance is None or not answers(instance):
        return False
    os.kill(instance.pid, 15)
    deadline = time.monotonic() + 5.0
    while time.monotonic() < deadline:
        try:
            os.kill(instance.pid, 0)
        except OSError:
            return True
        time.sleep(0.05)
    return True
