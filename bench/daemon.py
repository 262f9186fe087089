"""The `ros2` graph daemon: complete answers, warm-daemon speed, SIGKILL-to-gone time.

With turtlesim, turtle_controller, add_two_ints_server and mimic running: 200 consecutive
`ros2 service list` and 200 `ros2 node list` (the first one starts the daemon), counting the
answers that miss anything; 10 first answers of fresh daemons (`ros2 daemon stop` before each),
timed and checked alike; the median wall time of warm-daemon `ros2 node list` / `service
list` next to a bare `python -c pass` measured in the same run; and how long a SIGKILLed node
stays listed.
"""

from __future__ import annotations

import os
import signal
import statistics
import subprocess
import sys
import time

from common import Row, Session, executable, verdict, wait_until

CALLS = 200
TIMED = 30
COLD_STARTS = 10  # `ros2 daemon stop` + `ros2 service list`: each answer the first of a daemon
COLD_LIMIT_S = 1.0
KILLS = 3
NODES = ['/add_two_ints_server', '/turtle_controller', '/turtle_mimic', '/turtlesim']
MUST_SERVE = ['/add_two_ints', '/turtle1/set_pen', '/spawn', '/turtlesim/list_parameters']
SPEED_LIMIT_S = 0.2
GONE_LIMIT_S = 3.0


def _run(env: dict[str, str], *args: str) -> tuple[float, str]:
    start = time.monotonic()
    result = subprocess.run(list(args), env=env, capture_output=True, text=True, timeout=60)
    return time.monotonic() - start, result.stdout


def _ros2(env: dict[str, str], *args: str) -> tuple[float, str]:
    return _run(env, 'ros2', *args)


def _start_nodes(s: Session) -> None:
    turtlesim = s.start('turtlesim', 'turtlesim_node', '--headless')
    turtlesim.wait_for_output(r'Spawning turtle \[turtle1\]', timeout=30)
    for package, name in (('my_robot_controller', 'turtle_controller'),
                          ('my_robot_controller', 'add_two_ints_server'),
                          ('turtlesim', 'mimic')):
        s.start(package, name)
    wait_until(lambda: _ros2(s.env, 'node', 'list', '--no-daemon')[1].split() == NODES, 60,
               'the four nodes to be listed')


def _serves_all(listing: str) -> bool:
    return all(f'{name}\n' in listing for name in MUST_SERVE)


def _completeness(env: dict[str, str], calls: int) -> tuple[int, int, list[float], list[float]]:
    subprocess.run(['ros2', 'daemon', 'stop'], env=env, capture_output=True, timeout=30)
    incomplete_services = incomplete_nodes = 0
    service_times, node_times = [], []
    for _ in range(calls):
        elapsed, out = _ros2(env, 'service', 'list')
        service_times.append(elapsed)
        incomplete_services += not _serves_all(out)
    for _ in range(calls):
        elapsed, out = _ros2(env, 'node', 'list')
        node_times.append(elapsed)
        incomplete_nodes += out.split() != NODES
    return incomplete_services, incomplete_nodes, service_times, node_times


def _cold_starts(env: dict[str, str], starts: int) -> tuple[int, list[float]]:
    """First answers of fresh daemons: how many missed anything, and their wall times."""
    incomplete, times = 0, []
    for _ in range(starts):
        subprocess.run(['ros2', 'daemon', 'stop'], env=env, capture_output=True, timeout=30)
        elapsed, out = _ros2(env, 'service', 'list')
        times.append(elapsed)
        incomplete += not _serves_all(out)
    return incomplete, times


def _speed(env: dict[str, str]) -> dict[str, float]:
    """Medians of warm calls, interleaved with the baseline so that load hits all alike."""
    samples: dict[str, list[float]] = {'node list': [], 'service list': [], 'python -c pass': []}
    for _ in range(TIMED):
        samples['node list'].append(_ros2(env, 'node', 'list')[0])
        samples['service list'].append(_ros2(env, 'service', 'list')[0])
        samples['python -c pass'].append(_run(env, sys.executable, '-c', 'pass')[0])
    return {name: statistics.median(values) for name, values in samples.items()}


def _sigkill_to_gone(s: Session) -> list[float]:
    times = []
    for index in range(KILLS):
        victim = s.start_argv([executable('my_robot_controller', 'add_two_ints_server'),
                               '--ros-args', '-r', f'__node:=victim{index}'])
        wait_until(lambda i=index: f'/victim{i}\n' in _ros2(s.env, 'node', 'list')[1], 30,
                   'the victim to be listed')
        os.killpg(victim.popen.pid, signal.SIGKILL)
        killed = time.monotonic()
        while f'/victim{index}\n' in _ros2(s.env, 'node', 'list')[1]:
            if time.monotonic() - killed > 30:
                break
        times.append(time.monotonic() - killed)
        victim.popen.wait()
    return times


def run(s: Session, calls: int = CALLS) -> tuple[list[Row], dict]:
    _start_nodes(s)
    try:
        missed_services, missed_nodes, service_times, node_times = _completeness(s.env, calls)
        missed_cold, cold_times = _cold_starts(s.env, COLD_STARTS)
        medians = _speed(s.env)
        gone = _sigkill_to_gone(s)
    finally:
        subprocess.run(['ros2', 'daemon', 'stop'], env=s.env, capture_output=True, timeout=30)
    base = medians['python -c pass']
    rows = [
        Row('daemon', f'incomplete `service list` answers of {calls}', str(missed_services), '0',
            verdict(missed_services == 0)),
        Row('daemon', f'incomplete `node list` answers of {calls}', str(missed_nodes), '0',
            verdict(missed_nodes == 0)),
        Row('daemon', f'first call (starts the daemon), median / max of {len(cold_times)} '
            'after `ros2 daemon stop`', f'{statistics.median(cold_times):.2f} / '
            f'{max(cold_times):.2f} s', f'<= {COLD_LIMIT_S:g} s (median)',
            verdict(statistics.median(cold_times) <= COLD_LIMIT_S)),
        Row('daemon', f'incomplete first answers of {len(cold_times)} fresh daemons',
            str(missed_cold), '0', verdict(missed_cold == 0)),
        Row('daemon', 'python -c pass, median (baseline)', f'{base * 1000:.0f} ms'),
    ]
    for verb in ('node list', 'service list'):
        value = medians[verb]
        rows.append(Row('daemon', f'warm `ros2 {verb}`, median', f'{value * 1000:.0f} ms '
                        f'({value / base:.1f}x baseline)', '<= 200 ms',
                        verdict(value <= SPEED_LIMIT_S)))
    rows.append(Row('daemon', 'SIGKILL to gone from `node list`, worst of '
                    f'{len(gone)}', f'{max(gone):.2f} s', '< 3 s',
                    verdict(max(gone) < GONE_LIMIT_S)))
    data = {'daemon': {'incomplete_services': missed_services, 'incomplete_nodes': missed_nodes,
                       'medians_s': medians, 'sigkill_to_gone_s': gone,
                       'service_list_s': service_times, 'node_list_s': node_times,
                       'incomplete_cold': missed_cold, 'cold_start_s': cold_times}}
    return rows, data
