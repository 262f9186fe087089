"""tf2 lookups per second, and how soon a late listener has a static frame.

    scripts/ws python bench/tf2_lookup.py [--seconds 2]     (or scripts/bench --only tf2)

lookup_transform on a 3-link interpolated chain and across a 100-frame tree (a binary
tree, 6 links between the two leaves), at time 0 (latest common time) and at a past time
between samples (interpolation and SLERP on every link), pinned to one core. Then a
static_transform_publisher runs for a second before a listener node starts: the time from
the listener's creation to its first successful lookup of the static frame.
"""

from __future__ import annotations

import argparse
import math
import os
import time

from common import Row, Session, session, verdict

SECONDS = 2.0  # per measurement
GOAL = 50_000  # lookups/s, 3-link chain, one core (issue 21)
SAMPLES = 10  # per frame: 10 s of history at 1 Hz


def _buffer(links: list[tuple[str, str]]):
    import rclpy.time
    from geometry_msgs.msg import TransformStamped
    from tf2_py import BufferCore
    from tf2_py.maths import quaternion_from_euler
    buffer = BufferCore()
    for second in range(SAMPLES):
        for index, (parent, child) in enumerate(links):
            t = TransformStamped()
            t.header.frame_id, t.child_frame_id = parent, child
            t.header.stamp = rclpy.time.Time(seconds=second).to_msg()
            t.transform.translation.x = 1.0 + 0.1 * second
            t.transform.translation.y = 0.5 * index
            q = t.transform.rotation
            q.x, q.y, q.z, q.w = quaternion_from_euler(0.1 * index, 0.0, 0.3 * second)
            buffer.set_transform(t, 'bench')
    return buffer


def _rate(buffer, target: str, source: str, when, seconds: float) -> float:
    lookup = buffer.lookup_transform_core
    count = 0
    started = time.perf_counter()
    deadline = started + seconds
    while True:
        for _ in range(1000):
            lookup(target, source, when)
        count += 1000
        now = time.perf_counter()
        if now >= deadline:
            return count / (now - started)


def lookup_rates(seconds: float) -> list[tuple[str, float]]:
    import rclpy.time
    chain = _buffer([('world', 'a'), ('a', 'b'), ('b', 'c')])
    tree = _buffer([(f'f{(i - 1) // 2}' if i else 'world', f'f{i}') for i in range(100)])
    latest, past = rclpy.time.Time(), rclpy.time.Time(seconds=4.5)
    # f63 and f94 are leaves of different subtrees: 6 and 7 links to their common ancestor.
    return [('3-link chain, time 0', _rate(chain, 'world', 'c', latest, seconds)),
            ('3-link chain, past time', _rate(chain, 'world', 'c', past, seconds)),
            ('100-frame tree leaf to leaf, time 0', _rate(tree, 'f63', 'f94', latest, seconds)),
            ('100-frame tree leaf to leaf, past time', _rate(tree, 'f63', 'f94', past, seconds))]


def late_listener(current: Session) -> float:
    """Seconds from a listener's creation to its first lookup of an already published
    static frame (/tf_static is transient-local)."""
    import rclpy.time
    from tf2_ros import Buffer, TransformListener
    publisher = current.start_argv(['ros2', 'run', 'tf2_ros', 'static_transform_publisher',
                                    '--z', '1', '--frame-id', 'world', '--child-frame-id', 'cam'])
    publisher.wait_for_output(r'Spinning until stopped', timeout=30)
    time.sleep(1.0)
    probe = current.probe('late_listener')
    try:
        started = time.monotonic()
        buffer = Buffer()
        listener = TransformListener(buffer, probe.node)
        while not buffer.can_transform('world', 'cam', rclpy.time.Time()):
            probe.spin_for(0.005)
            if time.monotonic() - started > 30:
                raise TimeoutError('no static frame within 30 s')
        elapsed = time.monotonic() - started
        listener.unregister()
    finally:
        probe.close()
    return elapsed


def run(current: Session, seconds: float = SECONDS) -> tuple[list[Row], dict]:
    affinity = os.sched_getaffinity(0)
    os.sched_setaffinity(0, {min(affinity)})  # one core, as the goal says
    try:
        rates = lookup_rates(seconds)
    finally:
        os.sched_setaffinity(0, affinity)
    rows = [Row('tf2 lookups', name, f'{rate:,.0f} /s',
                f'>= {GOAL:,} /s' if name.startswith('3-link') else '',
                verdict(rate >= GOAL) if name.startswith('3-link') else '')
            for name, rate in rates]
    late = late_listener(current)
    rows.append(Row('tf2 lookups', 'late listener to its first static frame', f'{late:.3f} s'))
    return rows, {'tf2_lookups': dict(rates), 'tf2_late_listener_s': late}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--seconds', type=float, default=SECONDS)
    options = parser.parse_args()
    if not math.isfinite(options.seconds) or not 0.1 <= options.seconds <= 60:
        parser.error('--seconds must be between 0.1 and 60')
    with session('tf2_lookup') as current:
        rows, _ = run(current, options.seconds)
    for row in rows:
        print(f'{row.metric}: {row.value} {row.target} {row.verdict}'.rstrip())


if __name__ == '__main__':
    main()
