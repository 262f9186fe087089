"""NavFn planning time: a 20 m path on a 0.05 m grid, median of repeated plans.

    scripts/ws python bench/nav_plan.py [--repeats 30]

The map is 21 x 21 m at 0.05 m (420 x 420 cells): three walls across the way with doors off
the straight line, and boxes between them, built as the global costmap builds it (static
layer from an OccupancyGrid, inflation layer with radius 0.55 m and cost_scaling_factor 3.0
around a 0.22 m robot). The planner plans from one side to the other: 19 m apart, a path of
about 29 m through the doors. Wall and process CPU time are both reported: on a shared
machine the CPU time is the planner's own cost, the wall time adds the wait for a core. The
goal is a median wall time <= 50 ms.
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np
from nav2_costmap_2d.footprint import footprint_from_parameters
from nav2_costmap_2d.inflation_layer import InflationLayer
from nav2_costmap_2d.layered_costmap import LayeredCostmap
from nav2_costmap_2d.static_layer import StaticLayer
from nav2_navfn_planner.navfn_planner import NavfnPlanner, path_length

GOAL_MS = 50.0
RESOLUTION = 0.05
CELLS = 420
START = (1.0, 10.5, 0.0)
GOAL = (20.0, 10.5, 0.0)


def bench_map() -> np.ndarray:
    """OccupancyGrid data (rows of y): three walls across the way, doors off the straight line,
    and boxes scattered between them."""
    grid = np.zeros((CELLS, CELLS), dtype=np.int8)
    grid[0, :] = grid[-1, :] = grid[:, 0] = grid[:, -1] = 100
    for x, door in ((100, (270, 320)), (210, (90, 140)), (320, (250, 300))):
        grid[:, x:x + 4] = 100
        grid[door[0]:door[1], x:x + 4] = 0
    rng = np.random.default_rng(7)
    for _ in range(30):
        x, y = rng.integers(20, CELLS - 30, size=2)
        if any(abs(x - wall) < 30 for wall in (100, 210, 320)):
            continue  # keep the doors' approaches open
        grid[y:y + 10, x:x + 10] = 100
    for cx, cy, _ in (START, GOAL):
        cell_x, cell_y = int(cx / RESOLUTION), int(cy / RESOLUTION)
        grid[cell_y - 15:cell_y + 15, cell_x - 15:cell_x + 15] = 0
    grid[0, :] = grid[-1, :] = grid[:, 0] = grid[:, -1] = 100
    return grid


def global_costmap() -> LayeredCostmap:
    layered = LayeredCostmap('map', rolling_window=False, track_unknown=True)
    static = StaticLayer('static_layer', layered, {}, {'track_unknown_space': True})
    inflation = InflationLayer('inflation_layer', layered,
                               {'inflation_radius': 0.55, 'cost_scaling_factor': 3.0})
    layered.add_plugin(static)
    layered.add_plugin(inflation)
    layered.set_footprint(footprint_from_parameters('[]', 0.22)[0])
    static.process_map(CELLS, CELLS, RESOLUTION, 0.0, 0.0, bench_map().ravel())
    layered.update_map(*START)
    return layered


def measure(repeats: int) -> dict[str, float]:
    layered = global_costmap()
    costmap = layered.costmap
    planner = NavfnPlanner('GridBased', {'tolerance': 0.5, 'allow_unknown': True})
    plan = planner.create_plan(costmap, START, GOAL)  # warm-up, and the path measured
    walls, cpus = [], []
    for _ in range(repeats):
        wall, cpu = time.perf_counter(), time.process_time()
        planner.create_plan(costmap, START, GOAL)
        walls.append((time.perf_counter() - wall) * 1e3)
        cpus.append((time.process_time() - cpu) * 1e3)
    updates = []
    for _ in range(max(3, repeats // 3)):
        began = time.process_time()
        layered.update_map(*START)
        updates.append((time.process_time() - began) * 1e3)
    straight = float(np.hypot(GOAL[0] - START[0], GOAL[1] - START[1]))
    return {'update_cpu_ms': statistics.median(updates), 'path_m': path_length(plan),
            'straight_m': straight, 'poses': len(plan),
            'wall_median_ms': statistics.median(walls), 'wall_min_ms': min(walls),
            'cpu_median_ms': statistics.median(cpus)}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--repeats', type=int, default=30)
    args = parser.parse_args()
    result = measure(max(1, args.repeats))
    print(f"map: {CELLS} x {CELLS} cells at {RESOLUTION} m; path {result['path_m']:.2f} m "
          f"({result['poses']} poses; straight line {result['straight_m']:.2f} m)")
    print(f"plan time, median of {args.repeats}: wall {result['wall_median_ms']:.1f} ms "
          f"(min {result['wall_min_ms']:.1f} ms), CPU {result['cpu_median_ms']:.1f} ms; "
          f"goal <= {GOAL_MS:.0f} ms: {'met' if result['wall_median_ms'] <= GOAL_MS else 'MISSED'}")
    print(f"global costmap update (static + inflation layers, {CELLS} x {CELLS}): "
          f"CPU {result['update_cpu_ms']:.1f} ms (median)")


if __name__ == '__main__':
    main()
