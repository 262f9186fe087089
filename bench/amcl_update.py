"""AMCL's filter update time: one scan through motion model, laser model and resampling.

    scripts/ws python bench/amcl_update.py [--repeats 30]

A 21 x 21 m map at 0.05 m (420 x 420 cells, walls and boxes), a 360-beam scan of which
max_beams = 60 are used, Nav2's default parameters otherwise. Each update follows 0.3 m of
odometry (past update_min_d), so every scan runs the whole filter: the particle count is
what KLD sampling leaves (between min_particles and max_particles). Reported: the median CPU
time per update for the likelihood-field and the beam model, at Nav2's 500..2000 particles
and with the cloud spread over the whole map (global localisation's 2000). The goal is an
update well inside a 10 Hz scan period: median CPU <= 20 ms for the likelihood field.
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np
from nav2_amcl.amcl_core import AmclCore
from nav2_amcl.laser_model import laser_data
from nav2_amcl.occupancy import AmclMap

GOAL_MS = 20.0
RESOLUTION = 0.05
CELLS = 420


def bench_map() -> AmclMap:
    grid = np.zeros((CELLS, CELLS), dtype=np.int8)
    grid[0, :] = grid[-1, :] = grid[:, 0] = grid[:, -1] = 100
    rng = np.random.default_rng(7)
    for _ in range(40):
        x, y = rng.integers(20, CELLS - 30, size=2)
        grid[y:y + 12, x:x + 12] = 100
    grid[190:230, 190:260] = 0  # the robot's drive stays free
    return AmclMap.from_grid(grid.ravel(), CELLS, CELLS, RESOLUTION, 0.0, 0.0)


def measure(model: str, repeats: int, global_start: bool) -> tuple[float, int]:
    core = AmclCore({'laser_model_type': model}, seed=1)
    amcl_map = bench_map()
    core.set_map(amcl_map)
    start = np.array([10.0, 10.5, 0.0])
    bearings = np.linspace(-np.pi, np.pi, 360, endpoint=False)
    scan = amcl_map.calc_range(start[0], start[1], bearings, 12.0)
    data = laser_data(scan, -np.pi, bearings[1] - bearings[0], 0.1, 12.0, core.laser_params)
    cpus, counts = [], []
    for _ in range(repeats):
        if global_start:
            core.global_localization()
        else:
            core.initial_pose(start, np.diag([0.25, 0.25, 0.07]))
        core.laser_received(np.zeros(3), data, np.zeros(3))  # first scan: no motion
        began = time.process_time()
        core.laser_received(np.array([0.3, 0.0, 0.0]), data, np.zeros(3))
        cpus.append((time.process_time() - began) * 1e3)
        counts.append(core.pf.sample_count)
    return statistics.median(cpus), int(statistics.median(counts))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--repeats', type=int, default=30)
    args = parser.parse_args()
    repeats = max(1, args.repeats)
    print(f'map: {CELLS} x {CELLS} cells at {RESOLUTION} m; 360-beam scan, max_beams 60')
    for model in ('likelihood_field', 'beam'):
        for global_start in (False, True):
            cpu, count = measure(model, repeats, global_start)
            start = 'global cloud' if global_start else 'initial pose'
            verdict = ''
            if model == 'likelihood_field' and not global_start:
                verdict = f"; goal <= {GOAL_MS:.0f} ms: {'met' if cpu <= GOAL_MS else 'MISSED'}"
            print(f'{model:16s} {start}: update CPU {cpu:.1f} ms (median of {repeats}, '
                  f'2000 particles in, {count} out){verdict}')


if __name__ == '__main__':
    main()
