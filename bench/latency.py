"""Pose latency: the publisher's source timestamp to the subscriber's callback, for
turtlesim's /turtle1/pose and, in the same run, a minimal rclpy publisher (the baseline)."""

from __future__ import annotations

import sys
import time

from turtlesim.msg import Pose

from common import BENCH, Row, Session, percentile, verdict

DURATION_S = 8.0


def run(session: Session, duration: float = DURATION_S) -> tuple[list[Row], dict]:
    session.start('turtlesim', 'turtlesim_node', '--headless').wait_for_output(r'Spawning turtle')
    session.start_argv([sys.executable, str(BENCH / 'baseline_pose_publisher.py')])
    # rclpy's EventsExecutor would cost the subscriber less per callback, but it cannot
    # call a callback that takes the message info (source timestamp) in rclpy 7.1.6.
    probe = session.probe('bench_latency')
    samples: dict[str, list[float]] = {'turtlesim pose': [], 'baseline publisher': []}

    def record(label: str):
        def on_pose(_pose: Pose, info: dict) -> None:
            # Both stamps come from the same system clock: publisher and subscriber share
            # the host.
            samples[label].append((time.time_ns() - info['source_timestamp']) / 1e6)
        return on_pose

    try:
        probe.node.create_subscription(Pose, '/turtle1/pose', record('turtlesim pose'), 7)
        probe.node.create_subscription(Pose, '/baseline_pose', record('baseline publisher'), 7)
        probe.spin_until(lambda: min(map(len, samples.values())) > 20, 15.0, 'the first poses')
        for values in samples.values():
            values.clear()
        probe.spin_for(duration)
    finally:
        probe.close()
    ours, base = samples['turtlesim pose'], samples['baseline publisher']
    p50, p99 = percentile(ours, 50), percentile(ours, 99)
    ratio = p50 / percentile(base, 50)
    rows = [
        Row('pose latency', f'p50 over {len(ours)} poses', f'{p50:.3f} ms', '< 0.3 ms',
            verdict(p50 < 0.3)),
        Row('pose latency', 'p99', f'{p99:.3f} ms'),
        Row('pose latency', f'baseline rclpy publisher p50 / p99 over {len(base)}',
            f'{percentile(base, 50):.3f} / {percentile(base, 99):.3f} ms'),
        Row('pose latency', 'ratio p50 ours / baseline', f'{ratio:.2f}'),
    ]
    return rows, {'latency': samples}
