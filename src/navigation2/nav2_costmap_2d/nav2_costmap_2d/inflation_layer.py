"""InflationLayer: costs that fall off with the distance to the nearest lethal cell.

Nav2's formula, on the distance d in cells (resolution r, inscribed radius ri):
    d == 0        -> 254 LETHAL_OBSTACLE
    d * r <= ri   -> 253 INSCRIBED_INFLATED_OBSTACLE
    otherwise     -> int(252 * exp(-cost_scaling_factor * (d * r - ri)))
for cells up to ceil(inflation_radius / r) cells away. Upstream grows the cells out with a
queue ordered by distance; here an exact Euclidean distance transform, limited to that radius
(a column pass, then a windowed row pass), gives each cell its nearest lethal cell.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from nav2_costmap_2d.cost_values import (
    FREE_SPACE,
    INSCRIBED_INFLATED_OBSTACLE,
    LETHAL_OBSTACLE,
    NO_INFORMATION,
)
from nav2_costmap_2d.costmap_2d import Costmap2D
from nav2_costmap_2d.costmap_layer import Layer, ParameterError


def compute_cost(distance_cells: np.ndarray | float, resolution: float, inscribed_radius: float,
                 cost_scaling_factor: float) -> np.ndarray:
    """InflationLayer::computeCost for distances in cells (arrays welcome)."""
    distance = np.asarray(distance_cells, dtype=np.float64)
    metres = distance * resolution
    with np.errstate(over='ignore'):
        factor = np.exp(-cost_scaling_factor * (metres - inscribed_radius))
    decayed = ((INSCRIBED_INFLATED_OBSTACLE - 1) * factor).astype(np.int64)
    cost = np.where(metres <= inscribed_radius, INSCRIBED_INFLATED_OBSTACLE, decayed)
    return np.where(distance == 0, LETHAL_OBSTACLE, cost).astype(np.uint8)


def distance_to_sources(sources: np.ndarray, max_cells: int) -> np.ndarray:
    """Euclidean distance (cells) from each cell to the nearest True cell; inf past max_cells."""
    ny, nx = sources.shape
    rows = np.arange(ny, dtype=np.float32)[:, None]
    far = np.float32(1e9)
    # vertical distance to the nearest source in the same column, from above and from below
    above = np.maximum.accumulate(np.where(sources, rows, -far), axis=0)
    below = np.minimum.accumulate(np.where(sources, rows, far)[::-1], axis=0)[::-1]
    column = np.minimum(rows - above, below - rows)
    column_sq = np.where(column <= max_cells, column * column, np.inf).astype(np.float32)
    best = column_sq.copy()
    # a source within max_cells lies within max_cells columns: a window of shifts is exact
    for dx in range(1, max_cells + 1):
        if dx >= nx:
            break
        shift = np.float32(dx * dx)
        np.minimum(best[:, dx:], column_sq[:, :-dx] + shift, out=best[:, dx:])
        np.minimum(best[:, :-dx], column_sq[:, dx:] + shift, out=best[:, :-dx])
    distance = np.sqrt(best, dtype=np.float32)
    distance[distance > max_cells] = np.inf
    return distance


class InflationLayer(Layer):
    """nav2_costmap_2d::InflationLayer."""

    def __init__(self, name: str, layered_costmap: Any,
                 params: Mapping[str, Any] | None = None) -> None:
        super().__init__(name, layered_costmap, params)
        self.inflation_radius: float = self.parameter('inflation_radius', 0.55)
        self.cost_scaling_factor: float = self.parameter('cost_scaling_factor', 10.0)
        self.inflate_unknown: bool = self.parameter('inflate_unknown', False)
        self.inflate_around_unknown: bool = self.parameter('inflate_around_unknown', False)
        if self.inflation_radius < 0:
            raise ParameterError(f'{name}.inflation_radius: must be >= 0, got '
                                 f'{self.inflation_radius}')
        self.inscribed_radius = 0.0
        self.warnings: list[str] = []
        self.on_footprint_changed()

    @property
    def cell_inflation_radius(self) -> int:
        return self.layered_costmap.costmap.cell_distance(self.inflation_radius)

    def on_footprint_changed(self) -> None:
        self.inscribed_radius = self.layered_costmap.inscribed_radius
        if self.inflation_radius < self.inscribed_radius:
            # upstream's error line, kept for the node to log
            self.warnings.append(
                f'The configured inflation radius ({self.inflation_radius:.3f}) is smaller than '
                f'the computed inscribed radius ({self.inscribed_radius:.3f}) of your footprint, '
                'it is highly recommended to set inflation radius to be at least as big as the '
                'inscribed radius to avoid collisions')

    def cost_at_distance(self, distance_cells: np.ndarray | float) -> np.ndarray:
        return compute_cost(distance_cells, self.layered_costmap.costmap.resolution,
                            self.inscribed_radius, self.cost_scaling_factor)

    def update_costs(self, master: Costmap2D) -> None:
        radius = self.cell_inflation_radius
        if not self.enabled or radius == 0 or master.size_x == 0 or master.size_y == 0:
            return
        grid = master.costmap
        sources = grid == LETHAL_OBSTACLE
        if self.inflate_around_unknown:
            sources |= grid == NO_INFORMATION
        if not sources.any():
            return
        distance = distance_to_sources(sources, radius)
        reached = np.isfinite(distance)
        cost = np.zeros(grid.shape, dtype=np.uint8)
        cost[reached] = self.cost_at_distance(distance[reached])
        unknown = grid == NO_INFORMATION
        # an unknown cell takes the inflated cost only when it is high enough (upstream's rule)
        if self.inflate_unknown:
            overwrite_unknown = unknown & (cost > FREE_SPACE)
        else:
            overwrite_unknown = unknown & (cost >= INSCRIBED_INFLATED_OBSTACLE)
        raised = reached & ~unknown & (cost > grid)
        grid[raised] = cost[raised]
        grid[overwrite_unknown] = cost[overwrite_unknown]
