"""Plane geometry the controller server and its plugins share: poses as (x, y, yaw).

A path is an (N, 3) float array of x, y, yaw in one frame; a transform between frames is a
pose (x, y, yaw) of the source frame's origin in the target frame, as TF gives it.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

Pose2D = tuple[float, float, float]


def yaw_of(q: Any) -> float:
    """tf2::getYaw of a geometry_msgs Quaternion."""
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def normalize_angle(angle: float | np.ndarray) -> float | np.ndarray:
    """angles::normalize_angle: into [-pi, pi) (floats and arrays)."""
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


def shortest_angular_distance(start: float | np.ndarray, end: float | np.ndarray
                              ) -> float | np.ndarray:
    """angles::shortest_angular_distance: end - start in [-pi, pi)."""
    return normalize_angle(end - start)


def compose(transform: Pose2D, poses: np.ndarray) -> np.ndarray:
    """Poses (N, 3) in a frame whose origin is `transform` -> the same poses in the outer frame."""
    tx, ty, tyaw = transform
    c, s = math.cos(tyaw), math.sin(tyaw)
    out = np.empty_like(poses, dtype=np.float64)
    out[:, 0] = tx + c * poses[:, 0] - s * poses[:, 1]
    out[:, 1] = ty + s * poses[:, 0] + c * poses[:, 1]
    out[:, 2] = normalize_angle(poses[:, 2] + tyaw)
    return out


def inverse(transform: Pose2D) -> Pose2D:
    tx, ty, tyaw = transform
    c, s = math.cos(tyaw), math.sin(tyaw)
    return (-c * tx - s * ty, s * tx - c * ty, -tyaw)


def to_frame(frame_pose: Pose2D, poses: np.ndarray) -> np.ndarray:
    """Poses (N, 3) -> the same poses in the frame whose origin is at `frame_pose`."""
    return compose(inverse(frame_pose), poses)


def segment_lengths(path: np.ndarray) -> np.ndarray:
    return np.hypot(np.diff(path[:, 0]), np.diff(path[:, 1]))


def path_length(path: np.ndarray, start: int = 0) -> float:
    """nav2_util::geometry_utils::calculate_path_length from pose `start` on."""
    if len(path) - start < 2:
        return 0.0
    return float(segment_lengths(path[start:]).sum())


def closest_index(path: np.ndarray, x: float, y: float, end: int | None = None) -> int:
    """Index of the pose nearest (x, y) among path[:end] (the first of equals, as min_by)."""
    part = path[:end] if end is not None else path
    if len(part) == 0:
        return 0
    return int(np.argmin(np.hypot(part[:, 0] - x, part[:, 1] - y)))


def first_after_integrated_distance(path: np.ndarray, distance: float, start: int = 0) -> int:
    """geometry_utils::first_after_integrated_distance: the first index past `distance`
    along the path from `start` (len(path) when the path is shorter)."""
    if len(path) - start < 2:
        return len(path)
    integrated = np.cumsum(segment_lengths(path[start:]))
    beyond = np.nonzero(integrated > distance)[0]
    return start + int(beyond[0]) + 1 if len(beyond) else len(path)
