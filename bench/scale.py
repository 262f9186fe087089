"""Many turtles: pose rate per turtle, tick cost, missed ticks; the controller under that load.

The probe samples 8 turtles' poses (turtlesim skips a pose nobody subscribes to). Once more
at SINK_AT turtles with every pose subscribed: bench/pose_sink.py, one more process, takes
all of them, so turtlesim publishes count x 62.5 poses/s to a reliable reader.
"""

from __future__ import annotations

import json
import math
import sys
import time
from itertools import pairwise
from pathlib import Path

from geometry_msgs.msg import Twist
from service_msgs.msg import ServiceEventInfo
from turtlesim.msg import Pose
from turtlesim.srv import SetPen, Spawn

from common import Row, Session, verdict

COUNTS = (1, 50, 200, 500, 1000)
SINK_AT = 1000
# Issue 24 item 3: 1000 turtles at 62.5 Hz per turtle, no tick missed (200: issue 11).
TARGET_AT = (200, 1000)
MEASURE_S = 10.0
SAMPLED_TURTLES = 8
TARGET_HZ = 62.5
TICK_S = 0.016
CALL_DELAY_S = 0.5  # the longest a set_pen call may take to follow its crossing
CONTROLLER_AT = 200
SPAWN_BATCH = 8


def _grid_positions(count: int) -> list[tuple[float, float]]:
    """Spread start points over the middle of the canvas, away from the walls."""
    side = max(1, math.ceil(math.sqrt(count)))
    step = 6.0 / side
    return [(2.5 + step * (i % side), 2.5 + step * (i // side)) for i in range(count)]


def _spawn_all(probe, count: int) -> list[str]:
    client = probe.node.create_client(Spawn, '/spawn')
    if not client.wait_for_service(timeout_sec=15.0):
        raise RuntimeError('/spawn did not appear')
    names: list[str] = []
    positions = _grid_positions(count)
    # Creating a turtle's 11 DDS entities slows down as the participant fills up: about 0.1 s
    # each at 500 turtles, 0.15 s at 1000.
    limit = max(120.0, 0.3 * count)
    deadline = time.monotonic() + limit
    # Batches stay within the service queues' depth (10 by default, per side).
    for first in range(0, count, SPAWN_BATCH):
        futures = [client.call_async(Spawn.Request(x=x, y=y, theta=0.0, name=''))
                   for x, y in positions[first:first + SPAWN_BATCH]]
        while not all(f.done() for f in futures):
            if time.monotonic() > deadline:
                raise RuntimeError(f'spawned {len(names)} of {count} turtles in {limit:g} s')
            probe.executor.spin_once(timeout_sec=0.1)
        names += [f.result().name for f in futures]
    if '' in names:
        raise RuntimeError('turtlesim refused a spawn')
    return names


def _missed_ticks(stamps_ns: list[int]) -> int:
    """Ticks without a pose: a gap of n periods between two poses means n - 1 missed."""
    return sum(max(0, round((b - a) / 1e9 / TICK_S) - 1) for a, b in pairwise(stamps_ns))


def run_one(session: Session, count: int, sink: bool = False) -> dict:
    stats_path = session.log_dir / f'tick-stats-{count}{"-sink" if sink else ""}.json'
    sink_path = session.log_dir / f'pose-sink-{count}.json'
    with_controller = count == CONTROLLER_AT
    args = ['--headless', '--tick-stats', str(stats_path)]
    if with_controller:
        args += ['--service-introspection', 'metadata']
    sim = session.start('turtlesim', 'turtlesim_node', *args)
    sim.wait_for_output(r'Spawning turtle')
    probe = session.probe(f'bench_scale_{count}')
    try:
        # The command publishers exist before the turtles (a fresh turtlesim names them
        # turtle2, turtle3, ...). Created after them, each new remote writer is paired by
        # Fast DDS against every local reader of turtlesim (11 entities a turtle): with 1000
        # turtles that discovery kept a turtlesim thread at 42 % of a core for tens of
        # seconds, into the measured window. Created first, each spawn pairs its one reader.
        def command_publisher(name: str):
            return probe.node.create_publisher(Twist, f'/{name}/cmd_vel', 7)

        first = 2 if with_controller else 1  # the controller drives turtle1
        early = {f'turtle{i}': command_publisher(f'turtle{i}') for i in range(first, count + 1)}
        names = ['turtle1', *_spawn_all(probe, count - 1)]
        driven = names[first - 1:]
        publishers = [early.get(n) or command_publisher(n) for n in driven]
        circle = Twist()
        circle.linear.x, circle.angular.z = 1.0, 1.0
        # Two commands a second keep every turtle inside turtlesim's 1 s command timeout.
        probe.node.create_timer(0.5, lambda: [p.publish(circle) for p in publishers])
        sink_process = None
        if sink:
            sink_process = session.start_argv(
                [sys.executable, str(Path(__file__).with_name('pose_sink.py')), str(sink_path),
                 *names])
            sink_process.wait_for_output('flowing', timeout=120)

        sampled = names[:: max(1, len(names) // SAMPLED_TURTLES)][:SAMPLED_TURTLES]
        stamps: dict[str, list[int]] = {n: [] for n in sampled}  # source timestamps, ns
        for name in sampled:
            probe.node.create_subscription(
                Pose, f'/{name}/pose',
                lambda _m, info, n=name: stamps[n].append(info['source_timestamp']), 7)

        # Crossings by turtle1's pose source timestamps, calls by the server's event stamps
        # (both the host's clock), so that a probe lagging under load counts them alike.
        crossings: list[int] = []
        calls: list[int] = []
        if with_controller:
            session.start('my_robot_controller', 'turtle_controller')
            last_side = [None]

            def on_turtle1_pose(pose: Pose, info: dict) -> None:
                side = pose.x >= 5.5
                if last_side[0] is not None and side != last_side[0]:
                    crossings.append(info['source_timestamp'])
                last_side[0] = side

            def on_set_pen_event(event) -> None:
                if event.info.event_type == ServiceEventInfo.REQUEST_RECEIVED:
                    calls.append(event.info.stamp.sec * 10**9 + event.info.stamp.nanosec)

            probe.node.create_subscription(Pose, '/turtle1/pose', on_turtle1_pose, 7)
            probe.node.create_subscription(SetPen.Event, '/turtle1/set_pen/_service_event',
                                           on_set_pen_event, 100)
        probe.spin_for(2.0)  # let every turtle start moving and discovery settle
        for values in stamps.values():
            values.clear()
        start_ns = time.time_ns()
        window = (start_ns, start_ns + int(MEASURE_S * 1e9))
        probe.spin_for(MEASURE_S)
        if sink_process is not None:
            sink_process.stop(timeout=20.0)
        probe.spin_for(2 * CALL_DELAY_S)  # what was sent in the window, received late
        for values in stamps.values():
            values[:] = [t for t in values if window[0] <= t < window[1]]
        rates = [len(values) / MEASURE_S for values in stamps.values()]
        if with_controller:
            crossings_during = sum(window[0] <= t < window[1] for t in crossings)
            # A call answers the crossing before it (within CALL_DELAY_S): count the calls
            # of the window shifted by that much.
            shift = int(CALL_DELAY_S * 1e9)
            calls_during = sum(window[0] + shift <= t < window[1] + shift for t in calls)
    finally:
        probe.close()
        sim.stop(timeout=20.0)
    stats = json.loads(stats_path.read_text())
    # A tick turtlesim missed leaves the same gap in every turtle's poses; the probe itself
    # losing a pose would hit one turtle only. So: the fewest missed ticks of any sampled turtle.
    missed = min(_missed_ticks(values) for values in stamps.values())
    received = json.loads(sink_path.read_text()) if sink else None
    return {
        'count': count, 'sink': sink, 'rate_min': min(rates), 'rate_mean': sum(rates) / len(rates),
        'tick_mean_ms': stats['cost_mean_ms'], 'tick_p99_ms': stats['cost_p99_ms'],
        'missed': missed, 'ticks': round(MEASURE_S / TICK_S),
        'crossings': crossings_during if with_controller else None,
        'set_pen_calls': calls_during if with_controller else None,
        'sink_rate': received['received'] / received['seconds'] if sink and received['seconds']
        else None,
    }


def run(session: Session, counts: tuple[int, ...] = COUNTS) -> tuple[list[Row], dict]:
    results = []
    runs = [(count, False) for count in counts] + [(SINK_AT, True)] * (SINK_AT in counts)
    for count, sink in runs:
        try:
            results.append(run_one(session, count, sink))
        except (RuntimeError, TimeoutError, OSError, KeyError, ValueError,
                AssertionError) as error:
            results.append({'count': count, 'sink': sink, 'error': str(error)})
    rows = []
    for r in results:
        if 'error' in r:
            rows.append(Row('scale', f'{r["count"]} turtles{" every pose subscribed" * r["sink"]}',
                            f'failed: {r["error"]}'))
            continue
        on_target = abs(r['rate_min'] - TARGET_HZ) <= 0.5 and r['missed'] == 0
        targeted = r['count'] in TARGET_AT and not r['sink']
        value = (f'{r["rate_min"]:.2f}/{r["rate_mean"]:.2f} Hz, {r["tick_mean_ms"]:.2f}/'
                 f'{r["tick_p99_ms"]:.2f} ms, {r["missed"]} of {r["ticks"]}')
        if r['sink']:
            value += (f', sink took {r["sink_rate"] or 0:,.0f} of '
                      f'{r["count"] * TARGET_HZ:,.0f} poses/s')
        rows.append(Row(
            'scale', f'{r["count"]} turtles{", every pose subscribed" * r["sink"]}: pose Hz '
            f'min/mean, tick cost mean/p99 (whole run), missed ticks in {MEASURE_S:g} s',
            value, '62.5 +- 0.5 Hz, 0 missed' if targeted else '',
            verdict(on_target) if targeted else ('holds' if on_target else 'breaks')))
        if r['crossings'] is not None:
            per = r['set_pen_calls'] / r['crossings'] if r['crossings'] else float('nan')
            rows.append(Row('controller under load',
                            f'{r["count"]} turtles: crossings, set_pen calls, calls/crossing',
                            f'{r["crossings"]}, {r["set_pen_calls"]}, {per:.2f}', '1.00',
                            verdict(r['crossings'] > 0 and r['set_pen_calls'] == r['crossings'])))
    return rows, {'scale': results}
