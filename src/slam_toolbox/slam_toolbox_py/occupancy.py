"""The occupancy grid of the pose graph's scans, as Karto's OccupancyGrid counts it.

Each node's scan is traced from the laser at the node's corrected pose: the cells its rays
pass count a pass, the cells they end in count a hit and a pass (a node counts a cell once).
A cell is occupied (100) when hits / passes >= occupancy_threshold and passes >=
minimum_pass_through, free (0) when passed that often with fewer hits, unknown (-1) else.
Beams that saw nothing within range clear space up to max_laser_range. A node's cells are
kept until its pose moves (a loop closure), so a map update retraces only what moved.
"""

from __future__ import annotations

import math

import numpy as np

OFFSET = 1 << 20  # cells are ids (cy + OFFSET) * 2 OFFSET + (cx + OFFSET): 52 km either way


class OccupancyMap:
    def __init__(self, resolution: float, max_range: float,
                 occupancy_threshold: float = 0.1, minimum_pass_through: int = 2) -> None:
        self.resolution = resolution
        self.max_range = max_range
        self.occupancy_threshold = occupancy_threshold
        self.minimum_pass_through = minimum_pass_through
        # node id -> (hits, misses, laser origin) in the robot frame
        self._scans: dict[int, tuple[np.ndarray, np.ndarray, np.ndarray]] = {}
        # node id -> (pose traced at, hit ids, pass ids)
        self._traced: dict[int, tuple[np.ndarray, np.ndarray, np.ndarray]] = {}

    def add(self, node: int, pose: np.ndarray, hits: np.ndarray,
            misses: np.ndarray | None = None, origin: np.ndarray | None = None) -> None:
        """A node's scan: hit points and the end points of beams that saw nothing (robot
        frame), and the laser's position in the robot frame."""
        ok = np.isfinite(hits).all(axis=1)
        empty = np.zeros((0, 2))
        self._scans[node] = (hits[ok], empty if misses is None else misses,
                             np.zeros(2) if origin is None else origin)
        self._traced.pop(node, None)

    def remove(self, node: int) -> None:
        self._scans.pop(node, None)
        self._traced.pop(node, None)

    def clear(self) -> None:
        self._scans.clear()
        self._traced.clear()

    def _ids(self, xy: np.ndarray) -> np.ndarray:
        cells = np.floor(xy / self.resolution).astype(np.int64) + OFFSET
        return cells[..., 1] * (2 * OFFSET) + cells[..., 0]

    def _trace(self, pose: np.ndarray, hits: np.ndarray, misses: np.ndarray,
               origin: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        c, s = math.cos(pose[2]), math.sin(pose[2])
        rot = np.array([[c, s], [-s, c]])
        start = origin @ rot + pose[:2]
        ends = np.concatenate([hits, misses]) @ rot + pose[:2]
        if len(ends) == 0:
            return np.zeros(0, np.int64), np.zeros(0, np.int64)
        step = self.resolution / 2
        lengths = np.hypot(*(ends - start).T)
        samples = math.ceil(lengths.max() / step) + 1
        t = np.arange(samples) * step
        inside = t[None, :] < lengths[:, None]  # up to, not into, the end cell
        direction = (ends - start) / np.maximum(lengths, 1e-9)[:, None]
        along = start + t[None, :, None] * direction[:, None, :]
        ids = self._ids(along)
        passes = np.unique(ids[inside])
        hit_ids = np.unique(self._ids(ends[:len(hits)]))
        return hit_ids, np.union1d(passes, hit_ids)

    def raster(self, poses: dict[int, np.ndarray]
               ) -> tuple[np.ndarray, int, int, tuple[float, float]]:
        """(data int8 row-major from the bottom row, width, height, origin x/y) of the nodes
        at `poses`; nodes without a pose are left out."""
        all_hits, all_passes = [], []
        for node, (hits, misses, origin) in self._scans.items():
            pose = poses.get(node)
            if pose is None:
                continue
            cached = self._traced.get(node)
            if cached is None or np.abs(cached[0][:2] - pose[:2]).max() > self.resolution / 4 \
                    or abs(cached[0][2] - pose[2]) > 0.002:
                cached = (pose.copy(), *self._trace(pose, hits, misses, origin))
                self._traced[node] = cached
            all_hits.append(cached[1])
            all_passes.append(cached[2])
        if not all_passes or not sum(len(p) for p in all_passes):
            return np.zeros(0, np.int8), 0, 0, (0.0, 0.0)
        passes = np.concatenate(all_passes)
        hits = np.concatenate(all_hits)
        cx, cy = passes % (2 * OFFSET), passes // (2 * OFFSET)
        x0, y0 = int(cx.min()), int(cy.min())
        width, height = int(cx.max()) - x0 + 1, int(cy.max()) - y0 + 1
        local = (cy - y0) * width + (cx - x0)
        pass_count = np.bincount(local, minlength=width * height)
        hx, hy = hits % (2 * OFFSET), hits // (2 * OFFSET)
        hit_count = np.bincount((hy - y0) * width + (hx - x0), minlength=width * height)
        data = np.full(width * height, -1, dtype=np.int8)
        seen = pass_count >= self.minimum_pass_through
        ratio = hit_count / np.maximum(pass_count, 1)
        data[seen] = 0
        data[seen & (ratio >= self.occupancy_threshold)] = 100
        origin = ((x0 - OFFSET) * self.resolution, (y0 - OFFSET) * self.resolution)
        return data, width, height, origin
