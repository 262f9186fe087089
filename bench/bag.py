"""ros2 bag record under load: 200 turtles' poses (200 x 62.5 Hz = 12,500 msg/s) for 10 s.

Run twice, once per recorder executor:
- `single` (ROS2BAG_EXECUTOR=single): the recorder stores each message's DDS publication
  sequence number (MCAP's `sequence`), one more per pose a turtle publishes, so a gap in a
  topic's sequence is a message it did not get: an exact drop count. What turtlesim really
  published in the window (it falls behind 62.5 Hz on a loaded machine) is their span.
- `events` (the default): no sequence numbers (rclpy's EventsExecutor cannot hand message
  info over), so drops are estimated: turtlesim publishes every turtle's pose in each tick,
  so over a window every topic has k or k + 1 poses; a topic with fewer than the most
  frequent topic's count minus one lost the difference (a lower bound).
The bag is read back with the `mcap` package's reader.
"""

from __future__ import annotations

import shutil
import signal
import time
from collections import defaultdict

from common import Row, Session, cpu_seconds, verdict
from scale import _spawn_all

TURTLES = 200
MEASURE_S = 10.0
WARM_UP_S = 3.0


def run(session: Session, turtles: int = TURTLES, duration: float = MEASURE_S
        ) -> tuple[list[Row], dict]:
    rows, data = [], {}
    for executor in ('events', 'single'):
        new_rows, data[f'bag_{executor}'] = run_one(session, executor, turtles, duration)
        rows += new_rows
    return rows, data


def run_one(session: Session, executor: str, turtles: int, duration: float
            ) -> tuple[list[Row], dict]:
    from mcap.reader import make_reader

    sim = session.start('turtlesim', 'turtlesim_node', '--headless')
    sim.wait_for_output(r'Spawning turtle')
    probe = session.probe('bench_bag')
    try:
        names = ['turtle1', *_spawn_all(probe, turtles - 1)]
    finally:
        probe.close()
    bag = session.log_dir / f'poses-{executor}'
    shutil.rmtree(bag, ignore_errors=True)  # the bag of an earlier run
    recorder = session.start_argv(['env', f'ROS2BAG_EXECUTOR={executor}', 'ros2', 'bag',
                                   'record', '--disable-keyboard-controls', '-o', str(bag),
                                   *(f'/{n}/pose' for n in names)])
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

    # Sequence numbers of the poses published inside the window, per turtle.
    path = next(bag.glob('*.mcap'))
    sequences: dict[str, list[int]] = defaultdict(list)
    total = 0
    with open(path, 'rb') as stream:
        for _schema, channel, message in make_reader(stream).iter_messages():
            total += 1
            if window_start <= message.publish_time < window_end:
                sequences[channel.topic].append(message.sequence)
    recorded = sum(len(v) for v in sequences.values())
    silent = turtles - len(sequences)  # turtles with nothing recorded in the window at all
    if executor == 'single':
        published = sum(max(v) - min(v) + 1 for v in sequences.values() if v)
    else:
        counts = [len(sequences.get(f'/{n}/pose', [])) for n in names]
        top = max(counts)
        published = recorded + sum(max(0, top - 1 - c) for c in counts)
    dropped = published - recorded
    size = path.stat().st_size
    result = {
        'executor': executor, 'turtles': turtles, 'window_s': duration, 'published': published,
        'recorded': recorded, 'dropped': dropped, 'silent_topics': silent,
        'published_rate': published / duration, 'recorder_cpu_percent': cpu,
        'bytes_per_message': size / max(1, total), 'file_bytes': size, 'bag_messages': total,
    }
    print(f'bench bag: {result}', flush=True)
    rows = [
        Row('bag', f'{executor}: {turtles} turtles\' poses, {duration:.0f} s: dropped of '
            f'{published:,} published' + (' (estimate)' if executor == 'events' else ''),
            f'{dropped:,}', '0', verdict(dropped == 0 and silent == 0)),
        Row('bag', f'{executor}: pose rate turtlesim reached (12,500 msg/s nominal)',
            f'{published / duration:,.0f} msg/s'),
        Row('bag', f'{executor}: recorder CPU', f'{cpu:.0f} % of a core'),
        Row('bag', f'{executor}: bytes per message (MCAP, uncompressed)',
            f'{size / max(1, total):.1f} B'),
    ]
    return rows, result
