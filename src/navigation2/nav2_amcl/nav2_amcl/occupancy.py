"""AMCL's own view of the map (upstream's `map_t`, `map_cspace.cpp`, `map_range.cpp`).

AMCL keeps a cell state (-1 free, 0 unknown, +1 occupied), the distance of each cell to the
nearest occupied one for the likelihood field, and casts rays for the beam model. Its cell
addressing is upstream's: a world point goes to cell floor((x - origin) / resolution + 0.5)
and cell i sits at origin + i * resolution, i.e. AMCL rounds where the rest of Nav2 truncates.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

FREE = -1
UNKNOWN = 0
OCCUPIED = 1
# Rays are cast in chunks of at most this many (ray, step) cells to bound memory.
_RAYCAST_CHUNK = 2_000_000


def occupancy_states(data: np.ndarray) -> np.ndarray:
    """OccupancyGrid values to AMCL's states, as convertMap: 0 free, 100 occupied, else unknown."""
    values = np.asarray(data)
    states = np.zeros(values.shape, dtype=np.int8)
    states[values == 0] = FREE
    states[values == 100] = OCCUPIED
    return states


def _row_distances(occupied: np.ndarray) -> np.ndarray:
    """Cells to the nearest occupied cell along each row (inf where a row has none)."""
    rows, cols = occupied.shape
    index = np.broadcast_to(np.arange(cols, dtype=np.float64), (rows, cols))
    left = np.where(occupied, index, -np.inf)
    left = np.maximum.accumulate(left, axis=1)
    right = np.where(occupied, index, np.inf)
    right = np.minimum.accumulate(right[:, ::-1], axis=1)[:, ::-1]
    return np.minimum(index - left, right - index)


def distance_map(states: np.ndarray, resolution: float, max_occ_dist: float) -> np.ndarray:
    """Metres from each cell to the nearest occupied cell, capped at `max_occ_dist`.

    Exact Euclidean distances between cell centres (what map_update_cspace's brushfire
    computes), in two passes: along rows, then the minimum over the column offsets that can
    still be within `max_occ_dist` - numpy work proportional to the grid times that window.
    """
    occupied = states == OCCUPIED
    rows = occupied.shape[0]
    row_cells = _row_distances(occupied)
    limit_cells = max_occ_dist / resolution
    window = int(np.ceil(limit_cells))
    squared = np.minimum(row_cells, window + 1.0) ** 2
    best = squared.copy()
    for offset in range(1, min(window, rows - 1) + 1):
        shifted = squared[offset:] + offset * offset
        np.minimum(best[:-offset], shifted, out=best[:-offset])
        shifted = squared[:-offset] + offset * offset
        np.minimum(best[offset:], shifted, out=best[offset:])
    return np.minimum(np.sqrt(best) * resolution, max_occ_dist)


@dataclass
class AmclMap:
    """The grid AMCL localises against: states[row (y), column (x)]."""

    states: np.ndarray
    resolution: float
    origin_x: float
    origin_y: float
    max_occ_dist: float = 0.0
    occ_dist: np.ndarray = field(default_factory=lambda: np.zeros((0, 0)))

    @classmethod
    def from_grid(cls, data: np.ndarray, width: int, height: int, resolution: float,
                  origin_x: float, origin_y: float) -> AmclMap:
        """From an OccupancyGrid's row-major data (int8 -1..100)."""
        states = occupancy_states(np.asarray(data).reshape(height, width))
        return cls(states, float(resolution), float(origin_x), float(origin_y))

    @property
    def size_x(self) -> int:
        return int(self.states.shape[1])

    @property
    def size_y(self) -> int:
        return int(self.states.shape[0])

    def update_cspace(self, max_occ_dist: float) -> None:
        """Precompute occ_dist (laser_likelihood_max_dist) for the likelihood field."""
        self.max_occ_dist = float(max_occ_dist)
        self.occ_dist = distance_map(self.states, self.resolution, self.max_occ_dist)

    def world_to_map(self, x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """MAP_GXWX / MAP_GYWY: cell indices (may be outside the map)."""
        i = np.floor((np.asarray(x) - self.origin_x) / self.resolution + 0.5).astype(np.int64)
        j = np.floor((np.asarray(y) - self.origin_y) / self.resolution + 0.5).astype(np.int64)
        return i, j

    def map_to_world(self, i: np.ndarray, j: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """MAP_WXGX / MAP_WYGY."""
        return (self.origin_x + np.asarray(i) * self.resolution,
                self.origin_y + np.asarray(j) * self.resolution)

    def valid(self, i: np.ndarray, j: np.ndarray) -> np.ndarray:
        return (i >= 0) & (i < self.size_x) & (j >= 0) & (j < self.size_y)

    def occ_dist_at(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """Distance to the nearest obstacle at world points; max_occ_dist off the map."""
        i, j = self.world_to_map(x, y)
        inside = self.valid(i, j)
        result = np.full(np.shape(i), self.max_occ_dist, dtype=np.float64)
        result[inside] = self.occ_dist[j[inside], i[inside]]
        return result

    def free_cells(self) -> tuple[np.ndarray, np.ndarray]:
        """World coordinates of the free cells (the uniform pose generator's support)."""
        j, i = np.nonzero(self.states == FREE)
        return self.map_to_world(i, j)

    def calc_range(self, x: np.ndarray, y: np.ndarray, angle: np.ndarray,
                   max_range: float) -> np.ndarray:
        """map_calc_range for many rays: distance to the first cell that is not free.

        Steps one cell at a time along the ray's major axis as Bresenham does (the minor
        axis rounded), stops on a cell that is off the map, occupied or unknown, and measures
        between cell positions; max_range where the ray meets nothing.
        """
        x, y, angle = np.broadcast_arrays(np.asarray(x, float), np.asarray(y, float),
                                          np.asarray(angle, float))
        shape = x.shape
        x, y, angle = x.ravel(), y.ravel(), angle.ravel()
        x0, y0 = self.world_to_map(x, y)
        x1, y1 = self.world_to_map(x + max_range * np.cos(angle), y + max_range * np.sin(angle))
        dx, dy = x1 - x0, y1 - y0
        steps = np.maximum(np.abs(dx), np.abs(dy))
        longest = int(steps.max(initial=0)) + 1
        result = np.full(x.shape, float(max_range))
        chunk = max(1, _RAYCAST_CHUNK // longest)
        t = np.arange(longest)
        for start in range(0, x.size, chunk):
            part = slice(start, start + chunk)
            n = np.maximum(steps[part], 1)[:, None]
            ci = x0[part, None] + np.round(t * dx[part, None] / n).astype(np.int64)
            cj = y0[part, None] + np.round(t * dy[part, None] / n).astype(np.int64)
            on_ray = t[None, :] <= steps[part, None]
            inside = self.valid(ci, cj)
            blocked = ~inside
            blocked[inside] = self.states[cj[inside], ci[inside]] != FREE
            blocked &= on_ray
            hit = blocked.any(axis=1)
            first = np.argmax(blocked, axis=1)
            rows = np.nonzero(hit)[0]
            cols = first[rows]
            dist = np.hypot(ci[rows, cols] - x0[part][rows],
                            cj[rows, cols] - y0[part][rows]) * self.resolution
            sub = result[part]
            sub[rows] = np.minimum(dist, max_range)
            result[part] = sub
        return result.reshape(shape)
