"""nav2_smoother::SimpleSmoother: a path's interior points pulled towards their neighbours.

Each iteration moves every interior point by w_data * (original - current) + w_smooth *
(previous + next - 2 current) until the summed change drops below `tolerance` or `max_its`
iterations pass; an iteration that puts a point on a cell costlier than MAX_NON_OBSTACLE
(and known) ends smoothing with the path before it. Upstream updates the points one after
another (Gauss-Seidel); here the odd points, then the even ones, are updated as numpy arrays
(red-black Gauss-Seidel: the same fixed point, 1000 iterations of a 300-point path in ~30 ms
instead of seconds of Python loops). Paths are cut where they reverse direction and each part
of 10 points or more is smoothed on its own; do_refinement repeats the whole smoothing
refinement_num more times. The orientations are then the directions to the next point.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass

import numpy as np

MAX_NON_OBSTACLE = 252
NO_INFORMATION = 255


class SmootherTimedOut(Exception):
    pass


@dataclass
class GridView:
    """What the smoother needs of a costmap: cells, resolution and origin."""

    data: np.ndarray  # (size_y, size_x) uint8
    resolution: float
    origin_x: float
    origin_y: float

    def costs(self, xy: np.ndarray) -> np.ndarray:
        """The cost under each point; points off the grid read as unknown."""
        mx = np.floor((xy[:, 0] - self.origin_x) / self.resolution).astype(int)
        my = np.floor((xy[:, 1] - self.origin_y) / self.resolution).astype(int)
        size_y, size_x = self.data.shape
        inside = (mx >= 0) & (my >= 0) & (mx < size_x) & (my < size_y)
        out = np.full(len(xy), NO_INFORMATION, dtype=int)
        out[inside] = self.data[my[inside], mx[inside]]
        return out


@dataclass
class SmootherParams:
    tolerance: float = 1e-10
    max_its: int = 1000
    w_data: float = 0.2
    w_smooth: float = 0.3
    do_refinement: bool = True
    refinement_num: int = 2
    enforce_path_inversion: bool = True


def direction_segments(xy: np.ndarray, yaw: np.ndarray, enforce: bool) -> list[tuple[int, int,
                                                                                     bool]]:
    """(start, end, reversing) index ranges, cut where the path changes direction of travel."""
    n = len(xy)
    if not enforce or n < 3:
        return [(0, n - 1, False)]
    segments = []
    start = 0
    for i in range(1, n - 1):
        a = xy[i] - xy[i - 1]
        b = xy[i + 1] - xy[i]
        if float(a @ b) < 0.0:  # the path turns back on itself: a cusp
            segments.append((start, i, False))
            start = i
    segments.append((start, n - 1, False))
    # a segment is reversing when it travels against its poses' headings
    result = []
    for s, e, _ in segments:
        d = xy[min(s + 1, e)] - xy[s]
        heading = np.array([math.cos(yaw[s]), math.sin(yaw[s])])
        result.append((s, e, bool(float(d @ heading) < 0.0)))
    return result


def _smooth_segment(original: np.ndarray, params: SmootherParams, grid: GridView | None,
                    deadline: float) -> tuple[np.ndarray, bool]:
    """Smooth one segment; (path, completed)."""
    path = original.copy()
    last = path.copy()
    n = len(path)
    odd, even = np.arange(1, n - 1, 2), np.arange(2, n - 1, 2)
    its = 0
    change = params.tolerance
    while change >= params.tolerance:
        its += 1
        change = 0.0
        if its >= params.max_its or time.monotonic() > deadline:
            return last, False
        for idx in (odd, even):
            before = path[idx].copy()
            path[idx] += params.w_data * (original[idx] - path[idx]) + params.w_smooth * (
                path[idx + 1] + path[idx - 1] - 2.0 * path[idx])
            change += float(np.abs(path[idx] - before).sum())
        if grid is not None:
            costs = grid.costs(path[1:-1])
            if np.any((costs > MAX_NON_OBSTACLE) & (costs != NO_INFORMATION)):
                return last, False  # the last path before the collision
        last = path.copy()
    return path, True


def smooth(xy: np.ndarray, yaw: np.ndarray, params: SmootherParams, grid: GridView | None,
           max_time: float) -> tuple[np.ndarray, np.ndarray, bool]:
    """Smoothed positions and orientations, and whether smoothing completed."""
    xy = np.asarray(xy, dtype=float).copy()
    yaw = np.asarray(yaw, dtype=float).copy()
    start = time.monotonic()
    deadline = start + max_time if max_time > 0.0 else math.inf
    success = True
    for s, e, reversing in direction_segments(xy, yaw, params.enforce_path_inversion):
        if time.monotonic() > deadline:
            raise SmootherTimedOut('Smoothing time exceed allowed duration')
        if e - s < 9:
            continue  # too short to be worth smoothing
        segment = xy[s:e + 1]
        rounds = 1 + (params.refinement_num if params.do_refinement else 0)
        for _ in range(rounds):
            segment, done = _smooth_segment(segment, params, grid, deadline)
            success = success and done
            if not done:
                break
        xy[s:e + 1] = segment
        d = np.diff(segment, axis=0)
        headings = np.arctan2(d[:, 1], d[:, 0]) + (math.pi if reversing else 0.0)
        yaw[s:e] = headings
    return xy, yaw, success
