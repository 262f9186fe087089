"""Can Qt open a window here? Checked before any QApplication exists, because Qt aborts.

With DISPLAY set but the X libraries of Qt's xcb plugin missing, or no X server answering at
that display, Qt prints "could not load the Qt platform plugin" and calls abort() from C++:
no Python exception to catch. So this module looks first, without loading the plugin: the
plugin's shared libraries (ldd), then the X server's socket. `python -m turtlesim_py.display`
prints the hint alone (used by scripts/setup).
"""

from __future__ import annotations

import ctypes.util
import os
import re
import socket
import subprocess
import sys
from pathlib import Path

# What a Debian/Ubuntu desktop, WSL or container image most often lacks for Qt 6's xcb plugin.
XCB_PACKAGES = ('libxcb-cursor0', 'libxcb-icccm4', 'libxcb-keysyms1')
FIX_LIBS = f'apt-get install {" ".join(XCB_PACKAGES)}'
FIX_HEADLESS = 'or unset DISPLAY / run with --headless'


def wants_window(headless: bool) -> bool:
    """A window is asked for: not --headless, a display is set, Qt's platform not offscreen."""
    if headless or not (os.environ.get('DISPLAY') or os.environ.get('WAYLAND_DISPLAY')):
        return False
    return os.environ.get('QT_QPA_PLATFORM', '') not in ('offscreen', 'minimal')


def xcb_plugin() -> Path | None:
    try:
        import PySide6
    except ImportError:
        return None
    plugin = Path(PySide6.__file__).parent / 'Qt' / 'plugins' / 'platforms' / 'libqxcb.so'
    return plugin if plugin.exists() else None


def missing_xcb_libraries() -> list[str]:
    """Shared libraries the xcb platform plugin needs and the dynamic linker cannot find."""
    # Qt >= 6.5 loads libxcb-cursor by name when the plugin starts: ldd does not list it.
    missing = {'libxcb-cursor.so.0'} if ctypes.util.find_library('xcb-cursor') is None else set()
    plugin = xcb_plugin()
    try:
        if plugin is None:
            raise FileNotFoundError
        out = subprocess.run(['ldd', str(plugin)], capture_output=True, text=True,
                             timeout=10).stdout
        missing.update(re.findall(r'^\s*(\S+) => not found', out, re.MULTILINE))
    except (OSError, subprocess.SubprocessError):
        # No ldd (or no plugin to ask): check the usual suspects by name.
        missing.update(f'lib{name}.so' for name in ('xcb-icccm', 'xcb-keysyms')
                       if ctypes.util.find_library(name) is None)
    return sorted(missing)


def x_server_problem(display: str) -> str | None:
    """Why no X server answers at `display` (e.g. ':0', 'localhost:10.0'), or None if one does."""
    match = re.fullmatch(r'(?:unix/)?([^:]*):(\d+)(?:\.\d+)?', display)
    if not match:
        return f'DISPLAY={display} is not a valid display name'
    host, number = match.group(1), int(match.group(2))
    path = f'/tmp/.X11-unix/X{number}'
    if host in ('', 'unix'):
        for address in ('\0' + path, path):  # Linux abstract socket first, then the file
            with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as sock:
                sock.settimeout(2.0)
                try:
                    sock.connect(address)
                    return None
                except OSError:
                    continue
        if host == 'unix':
            return f'no X server answers at DISPLAY={display} ({path})'
        host = 'localhost'
    try:
        with socket.create_connection((host, 6000 + number), timeout=2.0):
            return None
    except OSError as error:
        return f'no X server answers at DISPLAY={display} ({error.strerror or error})'


def window_problem() -> str | None:
    """One line naming why Qt cannot open a window here and the fix; None when it can."""
    display = os.environ.get('DISPLAY')
    if not display:
        wayland = os.environ.get('WAYLAND_DISPLAY', '')
        runtime = os.environ.get('XDG_RUNTIME_DIR', '')
        if wayland and not Path(runtime, wayland).exists():
            return (f'no Wayland compositor at WAYLAND_DISPLAY={wayland} '
                    f'(fix: unset WAYLAND_DISPLAY / run with --headless)')
        return None
    if os.environ.get('QT_QPA_PLATFORM', 'xcb').split(':')[0] != 'xcb':
        return None
    missing = missing_xcb_libraries()
    if missing:
        return (f'DISPLAY={display} is set but Qt cannot use it: missing {", ".join(missing)} '
                f'(fix: {FIX_LIBS}, {FIX_HEADLESS})')
    problem = x_server_problem(display)
    if problem:
        return f'{problem} (fix: start the X server, {FIX_HEADLESS})'
    return None


def main() -> int:
    """Print the hint when a display is set and Qt could not use it; always exit 0."""
    if os.environ.get('DISPLAY'):
        missing = missing_xcb_libraries()
        if missing:
            print(f'hint: DISPLAY is set but turtlesim windows need {", ".join(missing)}: '
                  f'{FIX_LIBS} (until then turtlesim runs headless)')
    return 0


if __name__ == '__main__':
    sys.exit(main())
