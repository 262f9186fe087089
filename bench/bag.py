"""ros2 bag record under load: 200 turtles' poses (200 x 62.5 Hz = 12,500 msg/s) for 10 s.

Dropped messages are counted from the bag itself: turtlesim publishes every turtle's pose in
each tick, so each tick found in the bag should hold one pose per turtle; a turtle missing
from a tick others have is a message the recorder lost (a tick missing for every turtle is
turtlesim's, reported apart). The bag is read back with the `mcap` package's reader.
"""

from __future__ import annotations

import signal
import time
from collections import defaultdict

from common import Row, Session, cpu_seconds, verdict
from scale import TICK_S, _spawn_all

TURTLES = 200
MEASURE_S = 10.0
WARM_UP_S = 3.0
SAME_TICK_NS = 4_000_000  # poses of one tick are stamped within this of each other


def _ticks(stamps: list[int]) -> list[int]:
    """Index of the tick of each (sorted) stamp: a new tick after a gap of SAME_TICK_NS."""
    indexes, tick, last = [], -1, None
    for stamp in stamps:
        if last is None or stamp - last > SAME_TICK_NS:
            tick += 1
        indexes.append(tick)
        last = stamp
    return indexes


def run(session: Session, turtles: int = TURTLES, duration: float = MEASURE_S
        ) -> tuple[list[Row], dict]:
    from mcap.reader import make_reader

    sim = session.start('turtlesim', 'turtlesim_node', '--headless')
    sim.wait_for_output(r'Spawning turtle')
    probe = session.probe('bench_bag')
    try:
        names = ['turtle1', *_spawn_all(probe, turtles - 1)]
    finally:
        probe.close()
    bag = session.log_dir / 'poses'
    recorder = session.start_argv(['ros2', 'bag', 'record', '--disable-keyboard-controls',
                                   '-o', str(bag), *(f'/{n}/pose' for n in names)])
    recorder.wait_for_output('All requested topics are subscribed', timeout=60)
    time.sleep(WARM_UP_S)
    before = cpu_seconds(recorder.popen.pid)
    window_start = time.time_ns()
    time.sleep(duration)
    window_end = time.time_ns()
    cpu = 100 * (cpu_seconds(recorder.popen.pid) - before) / ((window_end - window_start) / 1e9)
    recorder.popen.send_signal(signal.SIGINT)
    recorder.popen.wait(timeout=60)
    sim.stop(timeout=20.0)

    # Publish (source) stamps of the poses sent inside the window, per turtle.
    path = next(bag.glob('*.mcap'))
    per_topic: dict[str, list[int]] = defaultdict(list)
    total = 0
    with open(path, 'rb') as stream:
        reader = make_reader(stream)
        for _schema, channel, message in reader.iter_messages():
            total += 1
            if window_start <= message.publish_time < window_end:
                per_topic[channel.topic].append(message.publish_time)
    stamps = sorted(s for values in per_topic.values() for s in values)
    tick_of = dict(zip(stamps, _ticks(stamps), strict=True))
    ticks = len(set(tick_of.values()))
    recorded = len(stamps)
    expected = ticks * turtles
    dropped = expected - recorded
    size = path.stat().st_size
    result = {
        'turtles': turtles, 'window_s': duration, 'ticks_in_bag': ticks,
        'ticks_nominal': round(duration / TICK_S), 'recorded': recorded,
        'expected': expected, 'dropped': dropped, 'recorder_cpu_percent': cpu,
        'bytes_per_message': size / max(1, total), 'file_bytes': size, 'bag_messages': total,
    }
    print(f'bench bag: {result}', flush=True)
    rows = [
        Row('bag', f'record {turtles} poses ({turtles * 62.5:,.0f} msg/s), {duration:.0f} s: '
            f'dropped of {expected:,}', f'{dropped:,}', '0', verdict(dropped == 0)),
        Row('bag', 'recorder CPU', f'{cpu:.0f} % of a core'),
        Row('bag', 'bytes per message (MCAP, uncompressed)',
            f'{size / max(1, total):.1f} B'),
        Row('bag', 'turtlesim ticks in the window', f'{ticks} of {round(duration / TICK_S)}'),
    ]
    return rows, {'bag': result}
