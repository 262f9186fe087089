"""Costmap2D: a grid of Nav2 cost values with its resolution, origin and world<->map maths.

Cells are stored row-major as upstream's char map (index = my * size_x + mx): `costmap[my, mx]`.
Nav2's conversions are kept to the letter: worldToMap truncates toward the origin and refuses
points left of or below it, mapToWorld gives a cell's centre, cellDistance rounds up.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from nav2_costmap_2d.cost_values import (
    INSCRIBED_INFLATED_OBSTACLE,
    LETHAL_OBSTACLE,
    NO_INFORMATION,
)


def _translation_table() -> np.ndarray:
    """Nav2's Costmap2DPublisher table: cost (0..255) -> OccupancyGrid value (-1, 0..100)."""
    table = np.zeros(256, dtype=np.int8)
    costs = np.arange(1, INSCRIBED_INFLATED_OBSTACLE)
    # integer maths as upstream: 1 + (97 * (i - 1)) / 251 in C++ ints
    table[1:INSCRIBED_INFLATED_OBSTACLE] = 1 + (97 * (costs - 1)) // 251
    table[INSCRIBED_INFLATED_OBSTACLE] = 99
    table[LETHAL_OBSTACLE] = 100
    table[NO_INFORMATION] = -1
    return table


COST_TRANSLATION_TABLE = _translation_table()


def costs_to_occupancy(costs: np.ndarray) -> np.ndarray:
    """Costs as the costmap topic publishes them: 0 free, 1..98 scaled, 99, 100, -1 unknown."""
    return COST_TRANSLATION_TABLE[np.asarray(costs, dtype=np.uint8)]


class Costmap2D:
    """A 2-D grid of costs (uint8), as nav2_costmap_2d::Costmap2D."""

    def __init__(self, size_x: int = 0, size_y: int = 0, resolution: float = 0.05,
                 origin_x: float = 0.0, origin_y: float = 0.0, default_value: int = 0) -> None:
        self.default_value = int(default_value)
        self.resize_map(size_x, size_y, resolution, origin_x, origin_y)

    # --- size and contents ---------------------------------------------------------------
    def resize_map(self, size_x: int, size_y: int, resolution: float, origin_x: float,
                   origin_y: float) -> None:
        if size_x < 0 or size_y < 0:
            raise ValueError(f'size_x, size_y: must be >= 0 cells, got {size_x} x {size_y}')
        if not resolution > 0:
            raise ValueError(f'resolution: must be > 0 m/cell, got {resolution}')
        self.size_x = int(size_x)
        self.size_y = int(size_y)
        self.resolution = float(resolution)
        self.origin_x = float(origin_x)
        self.origin_y = float(origin_y)
        self.costmap = np.full((self.size_y, self.size_x), self.default_value, dtype=np.uint8)

    def reset_map(self, x0: int = 0, y0: int = 0, xn: int | None = None,
                  yn: int | None = None) -> None:
        """Cells [x0, xn) x [y0, yn) back to the default value (all of them without bounds)."""
        self.reset_map_to_value(x0, y0, xn, yn, self.default_value)

    def reset_map_to_value(self, x0: int, y0: int, xn: int | None, yn: int | None,
                           value: int) -> None:
        xn = self.size_x if xn is None else xn
        yn = self.size_y if yn is None else yn
        self.costmap[y0:yn, x0:xn] = value

    def set_default_value(self, value: int) -> None:
        self.default_value = int(value)

    def get_cost(self, mx: int, my: int) -> int:
        return int(self.costmap[my, mx])

    def set_cost(self, mx: int, my: int, cost: int) -> None:
        self.costmap[my, mx] = cost

    def get_index(self, mx: int, my: int) -> int:
        return my * self.size_x + mx

    def index_to_cells(self, index: int) -> tuple[int, int]:
        return index % self.size_x, index // self.size_x

    @property
    def size_in_meters_x(self) -> float:
        # upstream's (size_x - 1 + 0.5) * resolution, kept as is
        return (self.size_x - 1 + 0.5) * self.resolution

    @property
    def size_in_meters_y(self) -> float:
        return (self.size_y - 1 + 0.5) * self.resolution

    # --- world <-> map -------------------------------------------------------------------
    def cell_distance(self, world_dist: float) -> int:
        return int(max(0.0, math.ceil(world_dist / self.resolution)))

    def map_to_world(self, mx: float, my: float) -> tuple[float, float]:
        """The centre of cell (mx, my) in the costmap's frame."""
        return (self.origin_x + (mx + 0.5) * self.resolution,
                self.origin_y + (my + 0.5) * self.resolution)

    def world_to_map(self, wx: float, wy: float) -> tuple[int, int] | None:
        """The cell holding (wx, wy), or None outside the map."""
        if wx < self.origin_x or wy < self.origin_y:
            return None
        mx = int((wx - self.origin_x) / self.resolution)
        my = int((wy - self.origin_y) / self.resolution)
        if mx < self.size_x and my < self.size_y:
            return mx, my
        return None

    def world_to_map_no_bounds(self, wx: float, wy: float) -> tuple[int, int]:
        return (int((wx - self.origin_x) / self.resolution),
                int((wy - self.origin_y) / self.resolution))

    def world_to_map_enforce_bounds(self, wx: float, wy: float) -> tuple[int, int]:
        if wx < self.origin_x:
            mx = 0
        elif wx > self.resolution * self.size_x + self.origin_x:
            mx = self.size_x - 1
        else:
            mx = int((wx - self.origin_x) / self.resolution)
        if wy < self.origin_y:
            my = 0
        elif wy > self.resolution * self.size_y + self.origin_y:
            my = self.size_y - 1
        else:
            my = int((wy - self.origin_y) / self.resolution)
        return mx, my

    def world_to_map_array(self, wx: np.ndarray, wy: np.ndarray) -> tuple[np.ndarray, np.ndarray,
                                                                           np.ndarray]:
        """Vectorised worldToMap: (mx, my, inside) for arrays of points."""
        fx = (np.asarray(wx, dtype=np.float64) - self.origin_x) / self.resolution
        fy = (np.asarray(wy, dtype=np.float64) - self.origin_y) / self.resolution
        inside = (fx >= 0) & (fy >= 0) & (fx < self.size_x) & (fy < self.size_y)
        return fx.astype(np.int64, copy=False), fy.astype(np.int64, copy=False), inside

    # --- rolling window ------------------------------------------------------------------
    def update_origin(self, new_origin_x: float, new_origin_y: float) -> None:
        """Move the window by whole cells, keeping what the old and new windows share."""
        cell_ox = int((new_origin_x - self.origin_x) / self.resolution)
        cell_oy = int((new_origin_y - self.origin_y) / self.resolution)
        new_grid_ox = self.origin_x + cell_ox * self.resolution
        new_grid_oy = self.origin_y + cell_oy * self.resolution
        x0 = min(max(cell_ox, 0), self.size_x)
        y0 = min(max(cell_oy, 0), self.size_y)
        x1 = min(max(cell_ox + self.size_x, 0), self.size_x)
        y1 = min(max(cell_oy + self.size_y, 0), self.size_y)
        kept = self.costmap[y0:y1, x0:x1].copy()
        self.costmap[:] = self.default_value
        self.origin_x, self.origin_y = new_grid_ox, new_grid_oy
        sx, sy = x0 - cell_ox, y0 - cell_oy
        self.costmap[sy:sy + kept.shape[0], sx:sx + kept.shape[1]] = kept

    # --- polygons ------------------------------------------------------------------------
    def polygon_mask(self, polygon: Sequence[tuple[float, float]]) -> np.ndarray:
        """Cells whose centres lie inside the polygon (world coordinates), as a bool grid."""
        mask = np.zeros((self.size_y, self.size_x), dtype=bool)
        if len(polygon) < 3 or self.size_x == 0 or self.size_y == 0:
            return mask
        pts = np.asarray(polygon, dtype=np.float64)
        lo = self.world_to_map_enforce_bounds(pts[:, 0].min(), pts[:, 1].min())
        hi = self.world_to_map_enforce_bounds(pts[:, 0].max(), pts[:, 1].max())
        xs = np.arange(lo[0], hi[0] + 1)
        ys = np.arange(lo[1], hi[1] + 1)
        cx = self.origin_x + (xs + 0.5) * self.resolution
        cy = self.origin_y + (ys + 0.5) * self.resolution
        px, py = np.meshgrid(cx, cy)
        inside = np.zeros(px.shape, dtype=bool)
        # even-odd rule over the polygon's edges
        for (x1, y1), (x2, y2) in zip(pts, np.roll(pts, -1, axis=0), strict=True):
            crosses = (y1 > py) != (y2 > py)
            with np.errstate(divide='ignore', invalid='ignore'):
                x_at = x1 + (py - y1) * (x2 - x1) / (y2 - y1)
            inside ^= crosses & (px < x_at)
        mask[lo[1]:hi[1] + 1, lo[0]:hi[0] + 1] = inside
        return mask

    def set_convex_polygon_cost(self, polygon: Sequence[tuple[float, float]], cost: int) -> bool:
        """Set every cell inside the polygon (and the cells of its vertices) to cost."""
        cells = [self.world_to_map(x, y) for x, y in polygon]
        if any(cell is None for cell in cells):
            return False
        self.costmap[self.polygon_mask(polygon)] = cost
        for mx, my in cells:
            self.costmap[my, mx] = cost
        return True

    # --- publishing ----------------------------------------------------------------------
    def to_occupancy_data(self) -> np.ndarray:
        """The OccupancyGrid data (int8, row-major) of Nav2's costmap publisher."""
        return costs_to_occupancy(self.costmap).ravel()

    def occupancy_origin(self) -> tuple[float, float]:
        """The OccupancyGrid origin the publisher writes: cell (0, 0)'s centre less half a cell."""
        wx, wy = self.map_to_world(0, 0)
        return wx - self.resolution / 2, wy - self.resolution / 2
