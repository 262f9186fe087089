"""turtlesim and displays: a display Qt cannot use gives one WARN line naming the cause and
the fix, and turtlesim carries on headless (Qt would abort); a display that works gets the
window (under Xvfb)."""

from __future__ import annotations

import ctypes
import ctypes.util
import os
import re
import shutil
import subprocess
import time
from pathlib import Path

import pytest
from turtlesim.srv import Spawn

FIX = 'apt-get install libxcb-cursor0 libxcb-icccm4 libxcb-keysyms1'


def display_env(ros_env: dict[str, str], display: str) -> dict[str, str]:
    env = dict(ros_env, DISPLAY=display)
    env.pop('QT_QPA_PLATFORM', None)  # the tests' default (offscreen) would skip the window
    env.pop('WAYLAND_DISPLAY', None)
    return env


def free_display() -> int:
    """A display number with no X server (nor lock file) on this machine."""
    for number in range(90 + os.getpid() % 50, 400):
        if not Path(f'/tmp/.X{number}-lock').exists() and \
                not Path(f'/tmp/.X11-unix/X{number}').exists():
            return number
    raise RuntimeError('no free display number')


def test_no_x_server_means_headless_with_one_line(ros_env, launch, probe):
    display = f':{free_display()}'
    sim = launch('turtlesim', 'turtlesim_node', env=display_env(ros_env, display))
    sim.wait_for_output(r'Spawning turtle \[turtle1\]', timeout=20)
    lines = re.findall(r'^.*No window.*$', sim.output, re.MULTILINE)
    assert len(lines) == 1, sim.output
    assert re.fullmatch(
        rf'\[WARN\] \[\d+\.\d+\] \[turtlesim\]: No window: (no X server answers at '
        rf'DISPLAY={display} \(.*\) \(fix: start the X server, or unset DISPLAY / run with '
        rf'--headless\)|DISPLAY={display} is set but Qt cannot use it: missing .* \(fix: '
        rf'{FIX}, or unset DISPLAY / run with --headless\)); running headless', lines[0])
    # Headless, but fully working.
    reply = probe.call(Spawn, '/spawn', Spawn.Request(x=2.0, y=2.0, name='t2'))
    assert reply.name == 't2'
    assert sim.stop() == 0, sim.output
    assert 'Traceback' not in sim.output and 'Aborted' not in sim.output


def test_missing_libraries_named_with_the_packages(monkeypatch):
    from turtlesim_py import display
    monkeypatch.setenv('DISPLAY', ':0')
    monkeypatch.delenv('QT_QPA_PLATFORM', raising=False)
    monkeypatch.setattr(display, 'missing_xcb_libraries',
                        lambda: ['libxcb-icccm.so.4', 'libxcb-keysyms.so.1'])
    assert display.window_problem() == (
        'DISPLAY=:0 is set but Qt cannot use it: missing libxcb-icccm.so.4, '
        f'libxcb-keysyms.so.1 (fix: {FIX}, or unset DISPLAY / run with --headless)')


def test_setup_hint_is_printed_not_failed(monkeypatch):
    from turtlesim_py import display
    script = Path(display.__file__).resolve()
    env = dict(os.environ, DISPLAY=':0')
    result = subprocess.run(['python', str(script)], env=env, capture_output=True, text=True,
                            timeout=30)
    assert result.returncode == 0
    if display.missing_xcb_libraries():
        assert FIX in result.stdout
    else:
        assert result.stdout == ''


def window_titles(display: str) -> list[str]:
    """Names of the top-level windows on an X display (Xlib through ctypes)."""
    xlib = ctypes.cdll.LoadLibrary(ctypes.util.find_library('X11'))
    xlib.XOpenDisplay.restype = ctypes.c_void_p
    xlib.XDefaultRootWindow.restype = ctypes.c_ulong
    xlib.XDefaultRootWindow.argtypes = [ctypes.c_void_p]
    xlib.XQueryTree.argtypes = [ctypes.c_void_p, ctypes.c_ulong, ctypes.POINTER(ctypes.c_ulong),
                                ctypes.POINTER(ctypes.c_ulong),
                                ctypes.POINTER(ctypes.POINTER(ctypes.c_ulong)),
                                ctypes.POINTER(ctypes.c_uint)]
    xlib.XFetchName.argtypes = [ctypes.c_void_p, ctypes.c_ulong,
                                ctypes.POINTER(ctypes.c_char_p)]
    xlib.XCloseDisplay.argtypes = [ctypes.c_void_p]
    handle = xlib.XOpenDisplay(display.encode())
    assert handle, f'cannot open {display}'
    try:
        root, parent = ctypes.c_ulong(), ctypes.c_ulong()
        children = ctypes.POINTER(ctypes.c_ulong)()
        count = ctypes.c_uint()
        xlib.XQueryTree(handle, xlib.XDefaultRootWindow(handle), ctypes.byref(root),
                        ctypes.byref(parent), ctypes.byref(children), ctypes.byref(count))
        titles = []
        for i in range(count.value):
            name = ctypes.c_char_p()
            if xlib.XFetchName(handle, children[i], ctypes.byref(name)) and name.value:
                titles.append(name.value.decode(errors='replace'))
        return titles
    finally:
        xlib.XCloseDisplay(handle)


def test_window_opens_under_xvfb(ros_env, launch, tmp_path):
    from turtlesim_py import display as probe_display
    if shutil.which('Xvfb') is None or ctypes.util.find_library('X11') is None:
        pytest.skip('needs Xvfb (apt-get install xvfb; scripts/test installs it as root)')
    missing = probe_display.missing_xcb_libraries()
    if missing:
        pytest.skip(f'needs {", ".join(missing)} ({FIX}; scripts/test installs them as root)')
    number = free_display()
    xvfb = launch(argv=['Xvfb', f':{number}', '-nolisten', 'tcp', '-screen', '0', '640x560x24'])
    socket_path = Path(f'/tmp/.X11-unix/X{number}')
    deadline = time.monotonic() + 15
    while not socket_path.exists():
        assert time.monotonic() < deadline and xvfb.popen.poll() is None, xvfb.output
        time.sleep(0.05)
    sim = launch('turtlesim', 'turtlesim_node', env=display_env(ros_env, f':{number}'))
    sim.wait_for_output(r'Spawning turtle \[turtle1\]', timeout=20)
    deadline = time.monotonic() + 15
    while 'TurtleSim' not in window_titles(f':{number}'):
        assert time.monotonic() < deadline, f'no TurtleSim window:\n{sim.output}'
        time.sleep(0.1)
    assert 'No window' not in sim.output
    assert sim.stop() == 0, sim.output
    assert 'Traceback' not in sim.output
