"""Every executable ends without a traceback on SIGINT or SIGTERM, whenever it comes.

Each executable is signalled at three points of its life: while starting (the moment rclpy's
library is loaded: imports, rclpy.init), once it works (its first line of output), and a
while later; the clients also while they wait for a server that never comes. It must exit
within a few seconds, with no traceback and no error exit (0, the shell's 128 + signal,
ros2cli's 2 for Ctrl-C, or the signal's own default action).
"""

from __future__ import annotations

import os
import pty
import signal
import subprocess
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

from support import executable

FLEXIBLE_URDF = Path(__file__).resolve().parents[2] / 'src/urdf_tutorial/urdf/06-flexible.urdf'
CLEAN = {0, 2, 130, 143, -signal.SIGINT, -signal.SIGTERM}
# (label, argv builder, a regex seen once it works, or None: wait 1.5 s instead)
SUBJECTS = [
    ('turtlesim_node', lambda: [executable('turtlesim', 'turtlesim_node'), '--headless'],
     r'Spawning turtle'),
    ('turtle_teleop_key', lambda: [executable('turtlesim', 'turtle_teleop_key')],
     r'Reading from keyboard'),
    ('draw_square', lambda: [executable('turtlesim', 'draw_square')], None),
    ('mimic', lambda: [executable('turtlesim', 'mimic')], None),
    ('turtle_controller', lambda: [executable('my_robot_controller', 'turtle_controller')],
     r'driving turtle1'),
    ('add_two_ints_server', lambda: [executable('my_robot_controller', 'add_two_ints_server')],
     r'Ready to add two ints'),
    # No server in this test: the client and `service call` wait for one.
    ('add_two_ints_client', lambda: [executable('my_robot_controller', 'add_two_ints_client')],
     r'not available, waiting again'),
    ('ros2 service call', lambda: ['ros2', 'service', 'call', '/add_two_ints_nobody',
                                   'example_interfaces/srv/AddTwoInts', '{a: 1, b: 2}'],
     r'waiting for service'),
    ('ros2 topic echo', lambda: ['ros2', 'topic', 'echo', '/turtle1/pose'], None),
    ('ros2 topic pub', lambda: ['ros2', 'topic', 'pub', '/turtle1/cmd_vel',
                                'geometry_msgs/msg/Twist', '{linear: {x: 1.0}}'], r'publish'),
    # --no-daemon: with the daemon, a missing node is answered without rclpy ever loading, so
    # there would be no 'starting' point to signal (the daemon path ends with exit code 2 too).
    ('ros2 param get', lambda: ['ros2', 'param', 'get', '--no-daemon', '/nobody_here', 'x'],
     None),
    ('joint_state_publisher', lambda: [executable('joint_state_publisher',
                                                  'joint_state_publisher'), str(FLEXIBLE_URDF)],
     None),
    # Signalled within its 5 s of listening (a stop writes no graph).
    ('view_frames', lambda: [executable('tf2_tools', 'view_frames')], r'Listening to tf data'),
]
POINTS = ('starting', 'working', 'later')


def run_and_signal(argv: list[str], env: dict[str, str], log: Path, ready: str | None,
                   point: str, signum: int) -> tuple[int | None, str]:
    """Start, signal at `point`, wait for the exit; (exit code or None if it hung, output)."""
    import re
    primary, replica = pty.openpty()  # teleop reads keys from a terminal
    with open(log, 'wb') as out:
        # cwd: whatever a subject writes (view_frames' graph) stays out of the repo.
        process = subprocess.Popen(argv, env=env, stdin=replica, stdout=out, cwd=log.parent,
                                   stderr=subprocess.STDOUT, start_new_session=True)
    os.close(replica)
    try:
        if point == 'starting':
            # As soon as rclpy's library is loaded: inside our imports and rclpy.init. (Before
            # that the interpreter and setuptools' entry-point wrapper are still importing the
            # standard library, where Ctrl-C gives any Python program a KeyboardInterrupt
            # traceback: docs/reliability.md.)
            deadline = time.monotonic() + 20.0
            while time.monotonic() < deadline and process.poll() is None:
                try:
                    if '_rclpy_pybind11' in Path(f'/proc/{process.pid}/maps').read_text():
                        break
                except OSError:
                    break
                time.sleep(0.01)
        else:
            deadline = time.monotonic() + 20.0
            while time.monotonic() < deadline and process.poll() is None:
                if ready is None and time.monotonic() > deadline - 18.5:
                    break
                if ready and re.search(ready, log.read_text(errors='replace')):
                    break
                time.sleep(0.05)
            if point == 'later':
                time.sleep(1.0)
        if process.poll() is None:
            if signum == signal.SIGINT:
                os.killpg(process.pid, signum)  # Ctrl-C reaches the terminal's process group
            else:
                os.kill(process.pid, signum)
        try:
            code: int | None = process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            code = None
            os.kill(process.pid, signal.SIGABRT)  # PYTHONFAULTHANDLER: every thread's stack
            try:
                process.wait(timeout=5)
            except subprocess.TimeoutExpired:
                os.killpg(process.pid, signal.SIGKILL)
                process.wait()
    finally:
        os.close(primary)
    return code, log.read_text(errors='replace')


@pytest.fixture(scope='module')
def shared_turtlesim(module_launch):
    sim = module_launch('turtlesim', 'turtlesim_node', '--headless')
    sim.wait_for_output(r'Spawning turtle', timeout=20)
    return sim


@pytest.mark.parametrize('label,argv,ready', SUBJECTS, ids=[s[0] for s in SUBJECTS])
def test_signals_end_cleanly(label, argv, ready, request, tmp_path):
    if label in ('turtlesim_node', 'add_two_ints_client', 'ros2 service call'):
        # Alone on a domain of their own: no other turtlesim, no server to find.
        ros_env = request.getfixturevalue('ros_env')
    else:
        # Something to work with: draw_square, mimic, the controller, teleop drive turtle1.
        # One turtlesim serves these cases (started once, up to its first turtle): only the
        # subject is signalled, and where the turtle has got to does not matter.
        request.getfixturevalue('shared_turtlesim')
        ros_env = request.getfixturevalue('module_ros_env')
    env = dict(ros_env, PYTHONFAULTHANDLER='1')
    cases = [(point, signum) for point in POINTS for signum in (signal.SIGINT, signal.SIGTERM)]
    with ThreadPoolExecutor(max_workers=len(cases)) as pool:
        results = list(pool.map(
            lambda case: run_and_signal(argv(), env, tmp_path / f'{case[0]}-{case[1]}.log',
                                        ready, *case), cases))
    problems = []
    for (point, signum), (code, output) in zip(cases, results, strict=True):
        name = signal.Signals(signum).name
        if code is None:
            problems.append(f'{name} while {point}: still running 10 s later\n{output}')
        elif code not in CLEAN or 'Traceback' in output:
            problems.append(f'{name} while {point}: exit code {code}\n{output}')
    assert not problems, f'{label}:\n' + '\n'.join(problems)
