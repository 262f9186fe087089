"""The turtle demo: one command (`ros2 launch` underneath) starts turtlesim and
turtle_controller and stops both cleanly."""

from __future__ import annotations

import os
import re
import signal
import time
from pathlib import Path

import pytest
from test_controller_turtlesim import count_canvas

from ws_testing import REPO, executable

STARTED = re.compile(r'^\[INFO\] \[(turtlesim_node|turtle_controller)-\d\]: process started '
                     r'with pid \[(\d+)\]$', re.MULTILINE)


def demo_env(ros_env):
    env = dict(ros_env)
    env.pop('DISPLAY', None)
    env.pop('WAYLAND_DISPLAY', None)
    return env


def child_pids(output: str) -> dict[str, int]:
    return {name: int(pid) for name, pid in STARTED.findall(output)}


def gone(pid: int) -> bool:
    """True when the process no longer exists (or is a zombie waiting to be reaped)."""
    try:
        state = Path(f'/proc/{pid}/stat').read_text().rsplit(')', 1)[1].split()[0]
    except (FileNotFoundError, ProcessLookupError):
        return True
    return state in ('Z', 'X')


def wait_gone(pids, timeout=10.0) -> bool:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if all(gone(pid) for pid in pids):
            return True
        time.sleep(0.05)
    return False


def assert_both_finished_cleanly(out: str, canvas: Path) -> None:
    for name in ('turtlesim_node-1', 'turtle_controller-2'):
        assert re.search(rf'^\[INFO\] \[{name}\]: process has finished cleanly \[pid \d+\]$',
                         out, re.MULTILINE), out
    assert f'[INFO] [launch.user]: final canvas saved: {canvas}' in out
    assert 'Traceback' not in out


def test_scripts_demo_runs_both_nodes_and_saves_the_canvas(launch, ros_env, tmp_path):
    canvas = tmp_path / 'demo.png'
    demo = launch(argv=[str(REPO / 'scripts' / 'demo'), '--seconds', '8',
                        '--canvas-png', str(canvas)], env=demo_env(ros_env))
    assert demo.wait(timeout=120) == 0, demo.output
    out = demo.output
    assert f"[demo] ROS_DOMAIN_ID={ros_env['ROS_DOMAIN_ID']}, " \
           'ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST' in out
    assert '[demo] window: none (no DISPLAY/WAYLAND_DISPLAY; running headless)' in out
    assert f'[demo] canvas PNG: {canvas}' in out
    assert re.search(r'^\[turtlesim_node-1\] \[INFO\] .*Starting turtlesim', out, re.MULTILINE)
    assert re.search(r'^\[turtle_controller-2\] \[INFO\] .*pen colour applied: green', out,
                     re.MULTILINE)
    assert '[INFO] [launch.user]: stopping (time is up)' in out
    assert_both_finished_cleanly(out, canvas)
    pids = child_pids(out)
    assert set(pids) == {'turtlesim_node', 'turtle_controller'}
    assert wait_gone(pids.values(), timeout=1.0)
    left, right = count_canvas(canvas)
    assert right.green > 300 and left.green == 0 and right.red == 0, (left, right)


@pytest.mark.parametrize('stop_signal', [signal.SIGINT, signal.SIGTERM])
def test_launcher_stops_both_nodes_on_ctrl_c_or_sigterm(launch, ros_env, tmp_path, stop_signal):
    canvas = tmp_path / 'canvas.png'
    demo = launch(argv=[executable('my_robot_controller', 'turtle_demo'),
                        '--canvas-png', str(canvas)], env=demo_env(ros_env))
    demo.wait_for_output(r'^\[turtle_controller-2\] .*pen colour applied', timeout=30)
    pids = child_pids(demo.output)
    # Ctrl-C in a terminal reaches the whole foreground process group; SIGTERM the launcher.
    if stop_signal == signal.SIGINT:
        os.killpg(demo.popen.pid, signal.SIGINT)
    else:
        demo.popen.send_signal(signal.SIGTERM)
    assert demo.wait(timeout=20) == 0, demo.output
    assert ('[WARNING] [launch]: user interrupted with ctrl-c (SIGINT)'
            if stop_signal == signal.SIGINT
            else '[WARNING] [launch]: SIGTERM received, stopping every process') in demo.output
    assert_both_finished_cleanly(demo.output, canvas)
    assert wait_gone(pids.values(), timeout=1.0)


def test_nodes_do_not_outlive_a_killed_launcher(launch, ros_env, tmp_path):
    demo = launch(argv=[executable('my_robot_controller', 'turtle_demo'),
                        '--canvas-png', str(tmp_path / 'canvas.png')], env=demo_env(ros_env))
    demo.wait_for_output(r'^\[INFO\] \[turtle_controller-2\]: process started', timeout=30)
    pids = child_pids(demo.output)
    demo.popen.send_signal(signal.SIGKILL)  # no chance to clean up: the kernel must
    demo.wait(timeout=5)
    assert wait_gone(pids.values(), timeout=10.0), pids


def test_launcher_reports_a_node_that_exits(launch, ros_env, tmp_path):
    demo = launch(argv=[executable('my_robot_controller', 'turtle_demo'),
                        '--canvas-png', str(tmp_path / 'canvas.png'), '--',
                        '--ros-args', '-p', 'pen_width:=0'], env=demo_env(ros_env))
    # Like `ros2 launch`, the demo exits 0 once everything stopped; the log says what happened.
    assert demo.wait(timeout=30) == 0, demo.output
    assert ("[turtle_controller-2] turtle_controller: error: parameter 'pen_width' = 0"
            in demo.output)
    assert '[INFO] [launch.user]: stopping (turtle_controller exited with code 2)' in demo.output
    # turtlesim is stopped by Ctrl-C: cleanly, or with 130 when the controller failed so early
    # that turtlesim was still importing (docs/reliability.md: quiet Ctrl-C while starting).
    assert re.search(r'^\[INFO\] \[turtlesim_node-1\]: process has finished cleanly|'
                     r'^\[ERROR\] \[turtlesim_node-1\]: process has died \[pid \d+, exit code 130,',
                     demo.output, re.MULTILINE), demo.output
    assert wait_gone(child_pids(demo.output).values(), timeout=1.0)
