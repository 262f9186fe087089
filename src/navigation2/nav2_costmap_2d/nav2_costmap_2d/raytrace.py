"""Upstream's raytraceLine (Bresenham) for many rays at once.

Costmap2D::raytraceLine walks from the sensor cell toward the end cell, stopping one cell
short of the end (that cell is the obstacle), shortened to max_length cells and started at
min_length cells. The cells a ray visits are those of bresenham2D: along the dominant axis
one cell per step, the other axis stepping when the accumulated error wraps.
"""

from __future__ import annotations

import numpy as np


def raytrace_cells(x0: int, y0: int, x1: np.ndarray, y1: np.ndarray, max_length: int,
                   min_length: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """(xs, ys) of every cell the rays (x0, y0) -> (x1[i], y1[i]) clear, duplicates allowed."""
    x1 = np.asarray(x1, dtype=np.int64)
    y1 = np.asarray(y1, dtype=np.int64)
    dx_full = x1 - x0
    dy_full = y1 - y0
    dist = np.hypot(dx_full, dy_full)
    keep = dist >= min_length
    x1, y1, dx_full, dy_full, dist = (a[keep] for a in (x1, y1, dx_full, dy_full, dist))
    safe = np.where(dist > 0, dist, 1.0)
    # start min_length cells along the ray (truncated toward zero, as the unsigned cast does)
    sx = np.where(dist > 0, (x0 + dx_full / safe * min_length).astype(np.int64), x0)
    sy = np.where(dist > 0, (y0 + dy_full / safe * min_length).astype(np.int64), y0)
    dx = x1 - sx
    dy = y1 - sy
    abs_dx, abs_dy = np.abs(dx), np.abs(dy)
    scale = np.where(dist == 0, 1.0, np.minimum(1.0, max_length / safe))
    x_major = abs_dx >= abs_dy
    abs_da = np.where(x_major, abs_dx, abs_dy)
    abs_db = np.where(x_major, abs_dy, abs_dx)
    steps = np.minimum((scale * abs_da).astype(np.int64), abs_da)
    total = int(steps.sum())
    if total == 0:
        return np.empty(0, dtype=np.int64), np.empty(0, dtype=np.int64)
    ray = np.repeat(np.arange(steps.size), steps)
    # the step number within each ray
    first = np.cumsum(steps) - steps
    i = np.arange(total) - first[ray]
    da = abs_da[ray]
    # error starts at abs_da / 2 and wraps each time it reaches abs_da: b advances by its quotient
    b_steps = (da // 2 + i * abs_db[ray]) // np.maximum(da, 1)
    sign_x = np.sign(dx)[ray]
    sign_y = np.sign(dy)[ray]
    major = x_major[ray]
    xs = sx[ray] + np.where(major, i, b_steps) * sign_x
    ys = sy[ray] + np.where(major, b_steps, i) * sign_y
    return xs, ys
