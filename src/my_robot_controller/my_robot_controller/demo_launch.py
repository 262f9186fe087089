"""The turtle demo: turtlesim and turtle_controller started together, like a launch file.

Both nodes run as child processes; their output is forwarded line by line with a
`[turtlesim]` / `[turtle_controller]` prefix. Ctrl-C, SIGTERM, `--seconds N` running out, or
either node exiting stops both (Ctrl-C first, then SIGTERM, then SIGKILL). The launcher first
asks turtlesim for the canvas PNG over /turtlesim/_save_canvas, then stops turtlesim (which
writes the PNG again as it exits) and only then the controller: stopped the other way round,
the turtle drove on for up to a second with nobody to switch its pen, and the final canvas
could show red right of the boundary. Every child is in its own process group and gets SIGTERM
from the kernel should this launcher die, so no process is ever left behind.
"""

from __future__ import annotations

import argparse
import ctypes
import os
import signal
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path
from types import FrameType

from ament_index_python.packages import PackageNotFoundError, get_package_prefix

DEFAULT_DOMAIN_ID = 77
STOP_GRACE = 5.0  # seconds a node gets to exit after Ctrl-C, and again after SIGTERM
PR_SET_PDEATHSIG = 1


def executable(package: str, name: str) -> str:
    """Path of an installed executable, found the way `ros2 run` finds it."""
    path = Path(get_package_prefix(package)) / 'lib' / package / name
    if not os.access(path, os.X_OK):
        raise FileNotFoundError(f'{package} has no executable {name} (looked at {path})')
    return str(path)


def has_display(env: dict[str, str]) -> bool:
    return bool(env.get('DISPLAY') or env.get('WAYLAND_DISPLAY'))


def _die_with_parent() -> None:
    # Runs in the child between fork and exec: if the launcher is killed outright (SIGKILL),
    # the kernel sends SIGTERM to the child instead of leaving it running unattended.
    libc = ctypes.CDLL(None, use_errno=True)
    libc.prctl(PR_SET_PDEATHSIG, signal.SIGTERM)


class Child:
    """One node process, its output forwarded with a prefix by a reader thread."""

    def __init__(self, label: str, argv: list[str], env: dict[str, str]) -> None:
        self.label = label
        # A session of its own: a Ctrl-C in the terminal reaches only the launcher, which
        # then stops the nodes in the right order (turtlesim first, then the controller).
        self.popen = subprocess.Popen(
            argv, env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
            stderr=subprocess.STDOUT, start_new_session=True, preexec_fn=_die_with_parent)
        self.reader = threading.Thread(target=self._forward, daemon=True)
        self.reader.start()
        say(f'started {label} (pid {self.popen.pid})')

    def _forward(self) -> None:
        assert self.popen.stdout is not None
        for raw in self.popen.stdout:
            line = raw.decode(errors='replace').rstrip('\n')
            print(f'[{self.label}] {line}', flush=True)

    def running(self) -> bool:
        return self.popen.poll() is None

    def stop(self) -> int:
        """Ctrl-C, then SIGTERM, then SIGKILL; return the exit code."""
        for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGKILL):
            if not self.running():
                break
            try:
                os.killpg(self.popen.pid, sig)
            except ProcessLookupError:
                break
            try:
                self.popen.wait(timeout=STOP_GRACE)
            except subprocess.TimeoutExpired:
                say(f'{self.label} did not exit after {signal.Signals(sig).name}')
        code = self.popen.wait()
        self.reader.join(timeout=2.0)
        return code


def save_canvas(domain_id: int, timeout: float = 5.0) -> str | None:
    """Ask turtlesim to write its canvas PNG now; its path, or None if it did not answer.

    Done before stopping anything, so the saved picture does not depend on how turtlesim
    handles its shutdown (it also writes the PNG then, if it can).
    """
    import rclpy
    from rclpy.context import Context
    from rclpy.executors import SingleThreadedExecutor
    from rclpy.signals import SignalHandlerOptions
    from std_srvs.srv import Trigger

    context = Context()
    rclpy.init(context=context, domain_id=domain_id,
               signal_handler_options=SignalHandlerOptions.NO)
    try:
        node = rclpy.create_node('_turtle_demo', context=context)
        client = node.create_client(Trigger, '/turtlesim/_save_canvas')
        if not client.wait_for_service(timeout_sec=timeout):
            return None
        future = client.call_async(Trigger.Request())
        executor = SingleThreadedExecutor(context=context)
        executor.add_node(node)
        executor.spin_until_future_complete(future, timeout_sec=timeout)
        if not future.done() or not future.result().success:
            return None
        return future.result().message
    finally:
        rclpy.try_shutdown(context=context)


def say(text: str) -> None:
    print(f'[demo] {text}', flush=True)


class StopRequested(Exception):
    pass


def _on_stop_signal(signum: int, frame: FrameType | None) -> None:
    raise StopRequested(signal.Signals(signum).name)


def parse_args(argv: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        prog='turtle_demo',
        description='Start turtlesim and turtle_controller together; Ctrl-C stops both.')
    parser.add_argument('--seconds', type=float, default=None,
                        help='stop after this many seconds (default: run until Ctrl-C)')
    parser.add_argument('--canvas-png', type=Path, default=None,
                        help='where turtlesim writes the canvas PNG '
                             '(default: a new directory under the temp dir)')
    parser.add_argument('--headless', action='store_true',
                        help='no window even when a display exists')
    parser.add_argument('controller_args', nargs='*', metavar='ROS_ARGS',
                        help="passed to turtle_controller after '--', e.g. "
                             "-- --ros-args -p boundary_x:=4.0")
    options = parser.parse_args(argv)
    if options.seconds is not None and options.seconds <= 0:
        parser.error(f'--seconds must be positive, got {options.seconds:g}')
    return options


def main(argv: list[str] | None = None) -> int:
    options = parse_args(sys.argv[1:] if argv is None else argv)
    env = dict(os.environ)
    env.setdefault('ROS_DOMAIN_ID', str(DEFAULT_DOMAIN_ID))
    # Keep DDS discovery on this machine (see the README's environment section).
    env['ROS_AUTOMATIC_DISCOVERY_RANGE'] = 'LOCALHOST'
    env['PYTHONUNBUFFERED'] = '1'
    os.environ.update(ROS_DOMAIN_ID=env['ROS_DOMAIN_ID'], ROS_AUTOMATIC_DISCOVERY_RANGE='LOCALHOST')

    canvas = options.canvas_png
    if canvas is None:
        canvas = Path(tempfile.mkdtemp(prefix='turtle-demo-')) / 'canvas.png'
    canvas = canvas.resolve()
    canvas.parent.mkdir(parents=True, exist_ok=True)
    headless = options.headless or not has_display(env)

    try:
        turtlesim_argv = [executable('turtlesim', 'turtlesim_node'), '--canvas-png', str(canvas)]
        controller_argv = [executable('my_robot_controller', 'turtle_controller'),
                           *options.controller_args]
    except (FileNotFoundError, PackageNotFoundError) as error:
        print(f'turtle_demo: error: {error} -- fix: run scripts/setup', file=sys.stderr)
        return 1
    if headless:
        turtlesim_argv.append('--headless')

    say(f"ROS_DOMAIN_ID={env['ROS_DOMAIN_ID']}, ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST")
    say('window: ' + ('none (no DISPLAY/WAYLAND_DISPLAY; running headless)' if headless
                      else f"turtlesim window on {env.get('WAYLAND_DISPLAY') or env['DISPLAY']}"))
    say(f'canvas PNG: {canvas}')
    say(f'stopping after {options.seconds:g} s' if options.seconds else 'Ctrl-C to stop')

    signal.signal(signal.SIGTERM, _on_stop_signal)
    signal.signal(signal.SIGINT, _on_stop_signal)
    children: list[Child] = []
    reason = 'time is up'
    failed = False
    started = time.monotonic()
    try:
        children.append(Child('turtlesim', turtlesim_argv, env))
        children.append(Child('turtle_controller', controller_argv, env))
        while options.seconds is None or time.monotonic() - started < options.seconds:
            exited = [child for child in children if not child.running()]
            if exited:
                reason = f'{exited[0].label} exited with code {exited[0].popen.returncode}'
                failed = True
                break
            time.sleep(0.1)
    except StopRequested as stop:
        reason = f'{stop} received'
    finally:
        # From here on a second Ctrl-C must not interrupt the clean stop.
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        signal.signal(signal.SIGTERM, signal.SIG_IGN)
        say(f'stopping ({reason})')
        saved = None
        if children and children[0].running():
            saved = save_canvas(int(env['ROS_DOMAIN_ID']))
        before = canvas.stat().st_mtime_ns if canvas.exists() else None
        for child in children:  # turtlesim first: no driving without a controller
            code = child.stop()
            say(f'{child.label} exited with code {code}')
    if saved or (canvas.exists() and canvas.stat().st_mtime_ns != before):
        say(f'final canvas saved: {canvas}')
    else:
        say(f'warning: turtlesim did not write the final canvas to {canvas}')
        failed = True
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
