"""Soak: set_pen under driving, spawn/kill cycles (memory), SIGKILLed turtlesim restarts.

1. 10,000 set_pen calls to turtle1 while turtle_controller drives it: every call answered.
2. 200 spawn + kill cycles: turtlesim's resident memory after them against before.
3. turtlesim SIGKILLed and restarted 20 times under one running turtle_controller: time from
   the controller hearing of the new turtle1 to its pen applied (the reply), each time.
Every part is bounded in count and time; run alone with `scripts/ws python bench/soak.py`.
"""

from __future__ import annotations

import argparse
import os
import re
import signal
import sys
import time
from pathlib import Path

from turtlesim.srv import Kill, SetPen, Spawn

from common import Row, Session, percentile, session, verdict

TURTLESIM = ('turtlesim', 'turtlesim_node', '--headless')
CONTROLLER = ('my_robot_controller', 'turtle_controller')


def rss_kib(pid: int) -> int:
    for line in Path(f'/proc/{pid}/status').read_text().splitlines():
        if line.startswith('VmRSS:'):
            return int(line.split()[1])
    raise RuntimeError('no VmRSS')


def call(probe, client, request, timeout: float = 5.0):
    future = client.call_async(request)
    deadline = time.monotonic() + timeout
    while not future.done() and time.monotonic() < deadline:
        probe.executor.spin_once(timeout_sec=0.05)
    if not future.done():
        client.remove_pending_request(future)
        return None
    return future.result()


def set_pen_under_driving(s: Session, calls: int) -> list[Row]:
    s.start(*TURTLESIM).wait_for_output(r'Spawning turtle')
    controller = s.start(*CONTROLLER)
    controller.wait_for_output(r'pen colour applied', timeout=30)
    probe = s.probe('soak_set_pen')
    try:
        client = probe.node.create_client(SetPen, '/turtle1/set_pen')
        if not client.wait_for_service(timeout_sec=15):
            raise RuntimeError('set_pen did not appear')
        lost = 0
        started = time.monotonic()
        window = 8  # requests in flight at once
        pending: list = []
        sent = 0
        deadline = started + 300
        while (sent < calls or pending) and time.monotonic() < deadline:
            while sent < calls and len(pending) < window:
                pending.append((client.call_async(SetPen.Request(r=sent % 256, g=0, b=0,
                                                                 width=3, off=0)),
                                time.monotonic()))
                sent += 1
            probe.executor.spin_once(timeout_sec=0.05)
            still = []
            for future, when in pending:
                if future.done():
                    continue
                if time.monotonic() - when > 5.0:
                    client.remove_pending_request(future)
                    lost += 1
                else:
                    still.append((future, when))
            pending = still
        lost += len(pending) + (calls - sent)
        elapsed = time.monotonic() - started
    finally:
        probe.close()
    driving = controller.popen.poll() is None
    return [Row('soak', f'set_pen calls while driving ({calls}, 8 in flight)',
                f'{calls - lost} answered, {lost} lost in {elapsed:.1f} s'
                f'{"" if driving else " (controller died)"}', '0 lost',
                verdict(lost == 0 and driving))]


def spawn_kill_cycles(s: Session, cycles: int) -> list[Row]:
    sim = s.start(*TURTLESIM)
    sim.wait_for_output(r'Spawning turtle')
    probe = s.probe('soak_spawn')
    try:
        spawn = probe.node.create_client(Spawn, '/spawn')
        kill = probe.node.create_client(Kill, '/kill')
        for client in (spawn, kill):
            if not client.wait_for_service(timeout_sec=15):
                raise RuntimeError('spawn/kill did not appear')

        def cycle(i: int) -> bool:
            name = f'soak{i}'
            reply = call(probe, spawn, Spawn.Request(x=1.0 + i % 9, y=2.0, theta=0.0, name=name))
            return reply is not None and reply.name == name and \
                call(probe, kill, Kill.Request(name=name)) is not None

        failed = sum(not cycle(i) for i in range(20))  # warm-up: caches, allocator pools
        time.sleep(1.5)  # retired action servers are destroyed a second after a kill
        before = rss_kib(sim.popen.pid)
        started = time.monotonic()
        failed += sum(not cycle(i) for i in range(cycles))
        elapsed = time.monotonic() - started
        time.sleep(1.5)
        after = rss_kib(sim.popen.pid)
    finally:
        probe.close()
    growth = (after - before) / before * 100
    return [Row('soak', f'{cycles} spawn/kill cycles: turtlesim RSS before -> after',
                f'{before / 1024:.1f} -> {after / 1024:.1f} MiB ({growth:+.1f} %), '
                f'{failed} failed, {elapsed:.1f} s', '< 5 % growth, 0 failed',
                verdict(growth < 5.0 and failed == 0))]


def _stamp(line: str) -> float:
    return float(re.match(r'\[\w+\] \[(\d+\.\d+)\]', line).group(1))


def restarts_under_controller(s: Session, restarts: int) -> list[Row]:
    """Per restart: from the controller hearing of the new turtle1 to the pen applied (both
    from the controller's log), and from turtlesim's start to the pen applied."""
    controller = s.start(*CONTROLLER)
    controller.wait_for_output(r'driving turtle1')
    heard_to_pen: list[float] = []
    start_to_pen: list[float] = []
    misses = 0
    for _ in range(restarts):
        mark = len(controller.output)
        started = time.time()
        sim = s.start(*TURTLESIM)
        sim.wait_for_output(r'Spawning turtle \[turtle1\]', timeout=20)
        deadline = time.monotonic() + 10
        applied = heard = None
        while time.monotonic() < deadline and applied is None:
            lines = controller.output[mark:].splitlines()
            heard_lines = [line for line in lines if re.search(
                r'a new turtle1 appeared|/turtle1/set_pen is available', line)]
            if heard_lines:
                heard = _stamp(heard_lines[0])
                applied = next((_stamp(line) for line in lines if 'pen colour applied' in line
                                and _stamp(line) >= heard), None)
            time.sleep(0.05)
        if applied is None:
            misses += 1
        else:
            heard_to_pen.append(applied - heard)
            start_to_pen.append(applied - started)
        os.killpg(sim.popen.pid, signal.SIGKILL)
        sim.popen.wait()
    worst = max(heard_to_pen) if heard_to_pen else float('nan')
    return [
        Row('soak', f'turtlesim SIGKILLed + restarted {restarts}x under the controller: '
            'controller hears of the new turtle1 -> pen applied, p50 / max',
            f'{percentile(heard_to_pen, 50):.2f} / {worst:.2f} s, {misses} not within 10 s',
            '< 1 s every time', verdict(misses == 0 and worst < 1.0)),
        Row('soak', 'same restarts: turtlesim started -> pen applied, p50 / max',
            f'{percentile(start_to_pen, 50):.2f} / '
            f'{max(start_to_pen, default=float("nan")):.2f} s'),
    ]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--quick', action='store_true', help='a tenth of the counts')
    parser.add_argument('--restarts-only', action='store_true', help='only the restart part')
    args = parser.parse_args()
    scale = 10 if args.quick else 1
    rows: list[Row] = []
    if not args.restarts_only:
        with session('soak_set_pen') as s:
            rows += set_pen_under_driving(s, 10_000 // scale)
        with session('soak_spawn_kill') as s:
            rows += spawn_kill_cycles(s, 200 // scale)
    with session('soak_restart') as s:
        rows += restarts_under_controller(s, max(2, 20 // scale))
    for row in rows:
        print(f'| {row.benchmark} | {row.metric} | {row.value} | {row.target} | {row.verdict} |')
    return 0 if all(row.verdict == 'met' for row in rows) else 1


if __name__ == '__main__':
    sys.exit(main())
