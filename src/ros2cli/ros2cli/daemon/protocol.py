"""What the daemon and its clients agree on: where the socket is, its version, the wire format.

One request per connection: the client sends one JSON object on one line, the daemon answers
with one JSON object on one line and closes. Imports nothing heavy (the client side of every
graph verb loads this module).
"""

from __future__ import annotations

import json
import os
import stat
from pathlib import Path
from typing import Any
from zlib import adler32, crc32

# Bump when requests or answers change shape; the package's source files' stamps are added
# to it so a daemon running older code (an edited workspace) is replaced too: it also runs
# verbs for the CLI (verb_host.py), so every module counts.
PROTOCOL = 3
# The settings that decide which DDS graph a process sees: a daemon serves exactly one set.
# A Fast DDS profile (e.g. the discovery-server page's super client) and the discovery
# server variables count: `ros2 topic list` after exporting them reaches a daemon made so.
SETTINGS = ('ROS_DOMAIN_ID', 'ROS_AUTOMATIC_DISCOVERY_RANGE', 'ROS_STATIC_PEERS',
            'RMW_IMPLEMENTATION', 'ROS_LOCALHOST_ONLY', 'ROS_DISCOVERY_SERVER',
            'ROS_SUPER_CLIENT', 'FASTRTPS_DEFAULT_PROFILES_FILE',
            'FASTDDS_DEFAULT_PROFILES_FILE')
PROFILE_SETTINGS = ('FASTRTPS_DEFAULT_PROFILES_FILE', 'FASTDDS_DEFAULT_PROFILES_FILE')
# What decides the code and interfaces a verb loads (a sourced overlay changes them): a
# process runs verbs only for CLIs whose values are its own; the daemon keeps one worker
# process per other set of values (server.py).
ENVIRONMENT = ('AMENT_PREFIX_PATH', 'PYTHONPATH', 'LD_LIBRARY_PATH', 'VIRTUAL_ENV',
               'RMW_IMPLEMENTATION', 'ROS_DISTRO')
MAX_MESSAGE = 64 * 1024 * 1024


class ProtocolError(Exception):
    """The other side sent something that is not one JSON object line."""


def version() -> str:
    package = Path(__file__).resolve().parent.parent
    stamps = []
    for directory, subdirectories, files in os.walk(package):
        subdirectories[:] = sorted(d for d in subdirectories if d != '__pycache__')
        for name in sorted(files):
            if name.endswith('.py'):
                info = os.stat(os.path.join(directory, name))
                stamps.append(f'{name}:{info.st_mtime_ns}:{info.st_size}')
    return f'{PROTOCOL}-{_digest(";".join(stamps))}'


def _digest(text: str) -> str:
    """64 bits of checksum: enough to tell a handful of settings apart, and no hashlib (whose
    OpenSSL load costs more than the rest of the client's imports)."""
    data = text.encode()
    return f'{crc32(data):08x}{adler32(data):08x}'


def settings(env: dict[str, str] | os._Environ[str] | None = None) -> dict[str, str]:
    """The graph-deciding settings of `env` (default: this process), unset ones as ''."""
    env = os.environ if env is None else env
    values = {name: env.get(name, '').strip() for name in SETTINGS}
    for name in PROFILE_SETTINGS:
        values[name] = _user_profile(values[name])
    return values


def _user_profile(path: str) -> str:
    """A profile file the user chose, absolute (the daemon runs in /); '' for none or for
    the workspace's own announcement profile (node_runtime.discovery sets it in processes)."""
    if not path:
        return ''
    from node_runtime.discovery import is_ours
    return '' if is_ours(path) else os.path.abspath(path)


def spawn_environment() -> dict[str, str]:
    """This process's environment for a daemon it starts: profile paths made absolute."""
    env = dict(os.environ)
    for name in PROFILE_SETTINGS:
        if env.get(name, '').strip():
            env[name] = os.path.abspath(env[name].strip())
    return env


def runtime_dir() -> Path:
    """The per-user directory of the daemons' sockets, created 0700 and checked to be ours.

    $XDG_RUNTIME_DIR (a 0700 tmpfs of the user's session) when set, else /tmp/ros2cli-UID.
    A directory that another user owns or that others can enter is refused: its socket could
    be someone else's.
    """
    xdg = os.environ.get('XDG_RUNTIME_DIR', '')
    if xdg and os.path.isdir(xdg):
        path = Path(xdg) / 'ros2cli'
    else:
        path = Path('/tmp') / f'ros2cli-{os.getuid()}'
    try:
        path.mkdir(mode=0o700)
    except FileExistsError:
        pass
    info = path.lstat()
    if not stat.S_ISDIR(info.st_mode) or info.st_uid != os.getuid() \
            or stat.S_IMODE(info.st_mode) & 0o077:
        raise PermissionError(f'{path} must be a directory of user {os.getuid()} with mode '
                              f'0700 (it is {stat.S_IMODE(info.st_mode):04o}, owner '
                              f'{info.st_uid}); remove it to let ros2 recreate it')
    return path


def socket_path(env: dict[str, str] | None = None) -> Path:
    """The socket of the daemon for `env`'s settings: one file per distinct set of settings."""
    values = settings(env)
    digest = _digest(json.dumps(values, sort_keys=True))
    domain = values['ROS_DOMAIN_ID'] or '0'
    return runtime_dir() / f'daemon-{domain}-{digest}.sock'


def environment() -> dict[str, str]:
    """This process's values of ENVIRONMENT, unset ones as ''."""
    return {name: os.environ.get(name, '') for name in ENVIRONMENT}


def worker_path(sock: Path, values: dict[str, str]) -> Path:
    """The socket of the daemon's worker for the environment `values` (next to `sock`)."""
    digest = _digest(json.dumps(values, sort_keys=True))
    return sock.with_name(f'{sock.stem}-env-{digest}.sock')


def lock_path(sock: Path) -> Path:
    """The daemon holds an exclusive flock on this file for as long as it runs."""
    return sock.with_suffix('.lock')


def encode(message: dict[str, Any]) -> bytes:
    return json.dumps(message, separators=(',', ':')).encode() + b'\n'


def decode(line: bytes) -> dict[str, Any]:
    try:
        message = json.loads(line)
    except ValueError as error:
        raise ProtocolError(f'not JSON: {error}') from None
    if not isinstance(message, dict):
        raise ProtocolError('not a JSON object')
    return message
