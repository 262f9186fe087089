"""Ctrl-C to exit of `ros2 bag record`, with metadata.yaml written (issue 24, item 5).

Three recorders, each stopped with SIGINT to its process group (as a terminal's Ctrl-C) RUNS
times: idle (its one topic has no publisher yet), the tutorial's (`/turtle1/cmd_vel
/turtle1/pose` of one turtlesim turtle), and 200 turtles' poses after 10 s of recording, the
turtles driving circles (12,500 msg/s, as bench/bag.py). Prints p50/p95 of the time from the
signal to the process's exit next to the 0.5 s target and the 5.1 s measured before, and
whether metadata.yaml existed and `ros2 bag info` read the bag at once after each exit.
The figures before (BEFORE_S) were measured side by side with the previous recorder (p50 of 3
runs): it drained its queues until nothing came for 50 ms, i.e. up to its 5 s bound whenever a
topic kept publishing, then Fast DDS's exit added 0.1 s.

    scripts/ws python bench/bag_stop.py [--runs N] [--turtles N] [--seconds S]
"""

from __future__ import annotations

import argparse
import os
import shutil
import signal
import subprocess
import time

from geometry_msgs.msg import Twist

from common import Row, Session, percentile, session, verdict
from scale import _spawn_all

RUNS = 10
TURTLES = 200
RECORD_S = 10.0
TARGET_S = 0.5
BEFORE_S = {'idle': 0.31, 'tutorial (1 turtle)': 5.18, 'turtles': 5.35}


def stop_once(session: Session, label: str, index: int, topics: list[str],
              record_s: float, during=None) -> tuple[float, bool]:
    """Record `topics` for `record_s`, Ctrl-C; (seconds to exit, bag readable right away)."""
    bag = session.log_dir / f'{label}-{index}'
    shutil.rmtree(bag, ignore_errors=True)
    recorder = session.start_argv(['ros2', 'bag', 'record', '--disable-keyboard-controls',
                                   '-o', str(bag), *topics])
    recorder.wait_for_output(r'Recording\.\.\.$', timeout=60)
    deadline = time.monotonic() + record_s
    while time.monotonic() < deadline:
        if during is not None:
            during()
        time.sleep(min(0.5, max(0.0, deadline - time.monotonic())))
    start = time.monotonic()
    os.killpg(recorder.popen.pid, signal.SIGINT)
    recorder.popen.wait(timeout=60)
    elapsed = time.monotonic() - start
    info = subprocess.run(['ros2', 'bag', 'info', str(bag)], env=session.env,
                          capture_output=True, text=True, timeout=30)
    readable = (recorder.popen.returncode == 0 and (bag / 'metadata.yaml').exists()
                and info.returncode == 0 and 'Messages:' in info.stdout)
    session.processes.remove(recorder)
    recorder.stop()  # closes its log
    shutil.rmtree(bag, ignore_errors=True)
    return elapsed, readable


def scenario(label: str, samples: list[float], readable: int, runs: int) -> list[Row]:
    p50, p95 = percentile(samples, 50), percentile(samples, 95)
    before = BEFORE_S.get(label, BEFORE_S['turtles'])
    print(f'bench bag_stop: {label}: p50 {p50:.3f} s, p95 {p95:.3f} s, max {max(samples):.3f} s,'
          f' bag readable at once {readable}/{runs} ({", ".join(f"{s:.3f}" for s in samples)})',
          flush=True)
    return [
        Row('bag_stop', f'{label}: Ctrl-C to exit p50 / p95 ({runs} runs; before: p50 '
            f'{before} s)', f'{p50:.2f} / {p95:.2f} s', f'p95 <= {TARGET_S} s',
            verdict(p95 <= TARGET_S)),
        Row('bag_stop', f'{label}: metadata.yaml there and `ros2 bag info` reads the bag at '
            'once after exit', f'{readable}/{runs}', f'{runs}/{runs}',
            verdict(readable == runs)),
    ]


def run(session: Session, runs: int = RUNS, turtles: int = TURTLES,
        record_s: float = RECORD_S) -> tuple[list[Row], dict]:
    rows, data = [], {}

    def measure(label, topics, seconds, during=None):
        results = [stop_once(session, label, i, topics, seconds, during) for i in range(runs)]
        samples = [elapsed for elapsed, _ in results]
        readable = sum(ok for _, ok in results)
        data[f'bag_stop_{label}'] = {'seconds': samples, 'readable': readable}
        rows.extend(scenario(label, samples, readable, runs))

    measure('idle', ['/nobody/publishes/this'], 1.0)

    sim = session.start('turtlesim', 'turtlesim_node', '--headless')
    sim.wait_for_output(r'Spawning turtle')
    measure('tutorial (1 turtle)', ['/turtle1/cmd_vel', '/turtle1/pose'], 2.0)

    probe = session.probe('bench_bag_stop')
    try:
        names = ['turtle1', *_spawn_all(probe, turtles - 1)]
        publishers = [probe.node.create_publisher(Twist, f'/{n}/cmd_vel', 7) for n in names]
        circle = Twist()
        circle.linear.x, circle.angular.z = 1.0, 1.0

        def drive() -> None:  # every 0.5 s: within turtlesim's 1 s command timeout
            for publisher in publishers:
                publisher.publish(circle)
        measure(f'{turtles} turtles, after {record_s:.0f} s',
                [f'/{n}/pose' for n in names], record_s, drive)
    finally:
        probe.close()
    return rows, data


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--runs', type=int, default=RUNS)
    parser.add_argument('--turtles', type=int, default=TURTLES)
    parser.add_argument('--seconds', type=float, default=RECORD_S)
    options = parser.parse_args()
    with session('bag_stop') as current:
        rows, _ = run(current, options.runs, options.turtles, options.seconds)
    for row in rows:
        print(f'{row.metric}: {row.value} (target {row.target}: {row.verdict})')


if __name__ == '__main__':
    main()
