"""The collision monitor's geometry (upstream's Polygon/Circle/Velocity maths), numpy only.

Points are (N, 2) arrays in the robot's base frame. A velocity is (vx, vy, wz); comparing two
velocities compares their linear speed, then their turn rate (upstream's Velocity::operator<).
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

Velocity = tuple[float, float, float]


def is_less(first: Velocity, second: Velocity) -> bool:
    """Upstream's Velocity::operator<: the slower linear speed, ties broken by |wz|."""
    a = first[0] ** 2 + first[1] ** 2
    b = second[0] ** 2 + second[1] ** 2
    if a < b:
        return True
    if a == b:
        return abs(first[2]) < abs(second[2])
    return False


def scale(velocity: Velocity, ratio: float) -> Velocity:
    return velocity[0] * ratio, velocity[1] * ratio, velocity[2] * ratio


def points_in_polygon(points: np.ndarray, vertices: np.ndarray) -> int:
    """How many points lie inside the polygon (even-odd crossings, as upstream)."""
    if len(points) == 0 or len(vertices) < 3:
        return 0
    x, y = points[:, 0][:, None], points[:, 1][:, None]
    xi, yi = vertices[:, 0][None, :], vertices[:, 1][None, :]
    xj, yj = np.roll(vertices[:, 0], 1)[None, :], np.roll(vertices[:, 1], 1)[None, :]
    crosses = (yi > y) != (yj > y)
    with np.errstate(divide='ignore', invalid='ignore'):
        x_at = (xj - xi) * (y - yi) / (yj - yi) + xi
    inside = np.logical_and(crosses, x < x_at).sum(axis=1) % 2 == 1
    return int(inside.sum())


def points_in_circle(points: np.ndarray, radius: float) -> int:
    if len(points) == 0:
        return 0
    return int((points[:, 0] ** 2 + points[:, 1] ** 2 < radius * radius).sum())


def circle_vertices(radius: float, count: int = 16) -> np.ndarray:
    angles = np.arange(count) * (2.0 * math.pi / count)
    return np.stack([radius * np.cos(angles), radius * np.sin(angles)], axis=1)


def collision_time(points: np.ndarray, inside: callable, velocity: Velocity,
                   time_before_collision: float, time_step: float, min_points: int) -> float:
    """Seconds until `min_points` points are inside the shape moving with `velocity`, or -1.

    The robot's pose is integrated step by step (the velocity is constant in the robot frame);
    the points are moved into each pose's frame and counted.
    """
    if inside(points) >= min_points:
        return 0.0
    px = py = theta = 0.0
    t = 0.0
    while t <= time_before_collision:
        px += (velocity[0] * math.cos(theta) - velocity[1] * math.sin(theta)) * time_step
        py += (velocity[0] * math.sin(theta) + velocity[1] * math.cos(theta)) * time_step
        theta += velocity[2] * time_step
        c, s = math.cos(theta), math.sin(theta)
        dx, dy = points[:, 0] - px, points[:, 1] - py
        moved = np.stack([c * dx + s * dy, -s * dx + c * dy], axis=1)
        if inside(moved) >= min_points:
            return t
        t += time_step
    return -1.0


def parse_points(text: str) -> np.ndarray:
    """Jazzy's `points` string '[[x, y], [x, y], ...]' (at least 3 points)."""
    import yaml  # a string parameter holding a YAML list, as upstream's parser reads it

    try:
        value = yaml.safe_load(text)
        array = np.asarray(value, dtype=float)
    except (yaml.YAMLError, ValueError, TypeError):
        raise ValueError(f"points '{text}' is not a list of [x, y] pairs") from None
    if array.ndim != 2 or array.shape[1] != 2 or len(array) < 3:
        raise ValueError(f"points '{text}' must hold at least 3 [x, y] pairs")
    if not np.isfinite(array).all():
        raise ValueError(f"points '{text}' must be finite")
    return array


def transform_points(points: Sequence[tuple[float, float]], tx: float, ty: float,
                     yaw: float) -> np.ndarray:
    array = np.asarray(points, dtype=float).reshape(-1, 2)
    c, s = math.cos(yaw), math.sin(yaw)
    return np.stack([tx + c * array[:, 0] - s * array[:, 1],
                     ty + s * array[:, 0] + c * array[:, 1]], axis=1)
