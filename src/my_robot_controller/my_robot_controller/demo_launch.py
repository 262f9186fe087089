"""The turtle demo's front end: `turtle_demo [--seconds N] [--canvas-png P] [--headless]`.

It says where things are (domain, window, canvas PNG), then becomes
`ros2 launch my_robot_controller turtle_demo.launch.py ...`, which starts turtlesim and
turtle_controller, prefixes their output, and stops both on Ctrl-C, SIGTERM, `--seconds`
running out or either node exiting (see launch/turtle_demo.launch.py and docs/launch.md).
"""

from __future__ import annotations

import argparse
import os
import shlex
import shutil
import sys
import tempfile
from pathlib import Path

DEFAULT_DOMAIN_ID = 77


def has_display(env: dict[str, str]) -> bool:
    return bool(env.get('DISPLAY') or env.get('WAYLAND_DISPLAY'))


def say(text: str) -> None:
    print(f'[demo] {text}', flush=True)


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
    os.environ.setdefault('ROS_DOMAIN_ID', str(DEFAULT_DOMAIN_ID))
    # Keep DDS discovery on this machine (see the README's environment section).
    os.environ['ROS_AUTOMATIC_DISCOVERY_RANGE'] = 'LOCALHOST'
    os.environ['PYTHONUNBUFFERED'] = '1'
    canvas = options.canvas_png
    if canvas is None:
        canvas = Path(tempfile.mkdtemp(prefix='turtle-demo-')) / 'canvas.png'
    canvas = canvas.resolve()
    canvas.parent.mkdir(parents=True, exist_ok=True)
    headless = options.headless or not has_display(os.environ)
    ros2 = shutil.which('ros2')
    if ros2 is None:
        print('turtle_demo: error: no ros2 command on the PATH -- fix: run scripts/setup',
              file=sys.stderr)
        return 1

    say(f"ROS_DOMAIN_ID={os.environ['ROS_DOMAIN_ID']}, ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST")
    display = os.environ.get('WAYLAND_DISPLAY') or os.environ.get('DISPLAY')
    say('window: ' + ('none (no DISPLAY/WAYLAND_DISPLAY; running headless)' if headless
                      else f'turtlesim window on {display}'))
    say(f'canvas PNG: {canvas}')
    say(f'stopping after {options.seconds:g} s' if options.seconds else 'Ctrl-C to stop')
    command = [ros2, 'launch', 'my_robot_controller', 'turtle_demo.launch.py',
               f'canvas_png:={canvas}', f'headless:={str(headless).lower()}',
               f'seconds:={options.seconds or 0:g}']
    if options.controller_args:  # `name:=` with nothing after it is malformed for ros2 launch
        command.append(f'controller_args:={shlex.join(options.controller_args)}')
    say(' '.join(shlex.quote(word) for word in ['ros2', *command[1:]]))
    os.execv(ros2, command)
    return 1  # not reached


if __name__ == '__main__':
    sys.exit(main())
