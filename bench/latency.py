"""Pose latency: the publisher's source timestamp to the subscriber's callback."""

from __future__ import annotations

import time

from turtlesim.msg import Pose

from common import Row, Session, percentile, verdict

DURATION_S = 8.0


def run(session: Session, duration: float = DURATION_S) -> tuple[list[Row], dict]:
    session.start('turtlesim', 'turtlesim_node', '--headless').wait_for_output(r'Spawning turtle')
    probe = session.probe('bench_latency')
    latencies_ms: list[float] = []

    def on_pose(_pose: Pose, info: dict) -> None:
        # Both stamps come from the same system clock: publisher and subscriber share the host.
        latencies_ms.append((time.time_ns() - info['source_timestamp']) / 1e6)

    try:
        probe.node.create_subscription(Pose, '/turtle1/pose', on_pose, 7)
        probe.spin_until(lambda: len(latencies_ms) > 20, 15.0, 'the first poses')
        latencies_ms.clear()
        probe.spin_for(duration)
    finally:
        probe.close()
    p50, p99 = percentile(latencies_ms, 50), percentile(latencies_ms, 99)
    rows = [
        Row('pose latency', f'p50 over {len(latencies_ms)} poses', f'{p50:.3f} ms', '< 0.3 ms',
            verdict(p50 < 0.3)),
        Row('pose latency', 'p99', f'{p99:.3f} ms'),
    ]
    return rows, {'latency': latencies_ms}
