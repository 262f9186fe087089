"""set_pen round trip against our turtlesim, next to a minimal rclpy SetBool server."""

from __future__ import annotations

import sys
import time

from std_srvs.srv import SetBool
from turtlesim.srv import SetPen

from common import BENCH, Row, Session, percentile, verdict

CALLS = 2000
BLOCK = 100  # calls alternate between the two servers in blocks, so drift hits both alike
TIME_BUDGET_S = 60.0


def _timed_calls(probe, client, request, count: int) -> list[float]:
    """Round trips in ms, each call_async spun to completion by the probe's executor."""
    samples = []
    for _ in range(count):
        start = time.perf_counter_ns()
        future = client.call_async(request)
        while not future.done():
            probe.executor.spin_once(timeout_sec=1.0)
        samples.append((time.perf_counter_ns() - start) / 1e6)
    return samples


def run(session: Session, calls: int = CALLS) -> tuple[list[Row], dict]:
    session.start('turtlesim', 'turtlesim_node', '--headless').wait_for_output(r'Spawning turtle')
    session.start_argv([sys.executable, str(BENCH / 'baseline_setbool_server.py')])
    probe = session.probe('bench_roundtrip')
    try:
        targets = {
            'turtlesim set_pen': (probe.node.create_client(SetPen, '/turtle1/set_pen'),
                                  SetPen.Request(r=255, g=0, b=0, width=3, off=0)),
            'baseline SetBool': (probe.node.create_client(SetBool, '/baseline_set_bool'),
                                 SetBool.Request(data=True)),
        }
        for label, (client, _) in targets.items():
            if not client.wait_for_service(timeout_sec=15.0):
                raise RuntimeError(f'{label}: service did not appear')
        samples: dict[str, list[float]] = {label: [] for label in targets}
        for client, request in targets.values():  # warm up discovery and caches
            _timed_calls(probe, client, request, 50)
        deadline = time.monotonic() + TIME_BUDGET_S
        while min(map(len, samples.values())) < calls and time.monotonic() < deadline:
            for label, (client, request) in targets.items():
                samples[label] += _timed_calls(probe, client, request, BLOCK)
    finally:
        probe.close()

    ours, base = samples['turtlesim set_pen'], samples['baseline SetBool']
    p50, p99 = percentile(ours, 50), percentile(ours, 99)
    ratio = p50 / percentile(base, 50)
    rows = [
        Row('set_pen round trip', f'p50 over {len(ours)} calls', f'{p50:.3f} ms', '< 1 ms',
            verdict(p50 < 1.0)),
        Row('set_pen round trip', 'p99', f'{p99:.3f} ms', '< 3 ms', verdict(p99 < 3.0)),
        Row('set_pen round trip', 'baseline SetBool p50 / p99',
            f'{percentile(base, 50):.3f} / {percentile(base, 99):.3f} ms'),
        Row('set_pen round trip', 'ratio p50 ours / baseline', f'{ratio:.2f}', '<= 1.2',
            verdict(ratio <= 1.2)),
    ]
    return rows, {'roundtrip': samples}
