"""Run the benchmark suite: `scripts/bench [--only NAME,...] [--quick]`.

Writes bench/results/results.md and PNG plots, and prints the table. Every benchmark runs
on its own leased ROS_DOMAIN_ID with ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST, with bounded
counts and durations, and stops every process it started.
"""

from __future__ import annotations

import argparse
import json
import time

import cli_speed
import sim

import bag
import bag_stop
import cpu
import daemon
import latency
import launch_time
import report
import roundtrip
import rqt
import rviz
import scale
import setup_time
import startup
import tf2_lookup
import turtle_tf2_cpu
from common import RESULTS, session

SUITE = {
    'roundtrip': lambda s, quick: roundtrip.run(s, calls=500 if quick else roundtrip.CALLS),
    'latency': lambda s, quick: latency.run(s, duration=3.0 if quick else latency.DURATION_S),
    'scale': lambda s, quick: scale.run(s, counts=(1, 50) if quick else scale.COUNTS),
    'cpu': lambda s, quick: cpu.run(s, duration=8.0 if quick else cpu.DURATION_S),
    'setup': lambda s, quick: setup_time.run(s),
    'daemon': lambda s, quick: daemon.run(s, calls=20 if quick else daemon.CALLS),
    'launch': lambda s, quick: launch_time.run(s, repeats=2 if quick else launch_time.REPEATS),
    'rqt': lambda s, quick: rqt.run(s, duration=20.0 if quick else rqt.DURATION_S),
    'bag': lambda s, quick: bag.run(s, turtles=50 if quick else bag.TURTLES),
    'bag_stop': lambda s, quick: bag_stop.run(s, runs=3 if quick else bag_stop.RUNS,
                                             turtles=50 if quick else bag_stop.TURTLES),
    'startup': lambda s, quick: startup.run(s, runs=2 if quick else startup.RUNS),
    'rviz': lambda s, quick: rviz.run(s, seconds=3.0 if quick else rviz.SECONDS),
    'tf2': lambda s, quick: tf2_lookup.run(s, seconds=0.5 if quick else tf2_lookup.SECONDS),
    'turtle_tf2_cpu': lambda s, quick: turtle_tf2_cpu.run(
        s, duration=8.0 if quick else turtle_tf2_cpu.DURATION_S),
    'cli_speed': lambda s, quick: cli_speed.run(s, runs=2 if quick else cli_speed.RUNS),
    'sim': lambda s, quick: sim.run(s, seconds=3.0 if quick else sim.SECONDS,
                                    runs=1 if quick else sim.RUNS),
}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--only', default=','.join(SUITE), help='comma-separated subset')
    parser.add_argument('--quick', action='store_true', help='short runs, for trying it out')
    options = parser.parse_args()
    RESULTS.mkdir(parents=True, exist_ok=True)
    started = time.monotonic()
    rows, data = [], {}
    for name in options.only.split(','):
        print(f'bench: {name} ...', flush=True)
        with session(name) as current:
            new_rows, new_data = SUITE[name](current, options.quick)
        rows += new_rows
        data.update(new_data)
    markdown = report.write_markdown(rows, time.monotonic() - started)
    plots = report.write_plots(data)
    (RESULTS / 'raw.json').write_text(json.dumps(data, indent=1, default=str))
    print(report.table(rows))
    print(f'\nbench: wrote {markdown} and {", ".join(p.name for p in plots)}')


if __name__ == '__main__':
    main()
