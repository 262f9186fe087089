"""Correlative scan matching (Olson's method, as Karto's ScanMatcher does it), with numpy.

A scan is matched against a likelihood field made from other scans' points: each cell holds
exp(-d^2 / 2 sigma^2), d its distance to the nearest point (sigma: the smear deviation). The
coarse search tries every translation of the field's lattice within the search window and
every angle step within the angular window; the score of a pose is the mean field value under
the scan's points, times Karto's distance and angle penalties. A fine search then refines
around the best pose on a finer lattice and angle step, reading the field bilinearly.
The covariance comes from the coarse scores near the best one (as Karto's
ComputePositionalCovariance and ComputeAngularCovariance).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import ndimage


@dataclass(frozen=True)
class SearchWindow:
    """Where a match looks, around its prior pose: half-widths and steps."""

    linear: float  # m, half the side of the square of translations
    resolution: float  # m, the field's cell and the coarse translation step
    smear: float  # m, the smear deviation of the field
    angular: float  # rad, half the range of angles
    angular_step: float  # rad, the coarse angle step
    fine_angular_step: float  # rad


@dataclass(frozen=True)
class Penalties:
    """Karto's penalties of a pose far from the prior (the parameters of the same names)."""

    distance_variance_penalty: float = 0.5
    angle_variance_penalty: float = 1.0
    minimum_distance_penalty: float = 0.5
    minimum_angle_penalty: float = 0.9


@dataclass
class Match:
    pose: np.ndarray  # x, y, theta in the field's frame
    response: float  # 0..1: mean field value under the points, penalised
    covariance: np.ndarray  # 3 x 3


def transform(points: np.ndarray, pose: np.ndarray) -> np.ndarray:
    """Points (N, 2) in a frame at `pose` (x, y, theta) into the parent frame."""
    c, s = math.cos(pose[2]), math.sin(pose[2])
    return points @ np.array([[c, s], [-s, c]]) + pose[:2]


class LikelihoodField:
    """The smeared points on a grid; rows are y, columns x; cell (r, c) centred at
    origin + ((c + 0.5) res, (r + 0.5) res)."""

    def __init__(self, grid: np.ndarray, origin: np.ndarray, resolution: float) -> None:
        self.grid = grid
        self.origin = origin
        self.resolution = resolution

    @classmethod
    def from_points(cls, points: np.ndarray, resolution: float, smear: float,
                    margin: float) -> LikelihoodField:
        lo = points.min(axis=0) - margin
        hi = points.max(axis=0) + margin
        shape = np.ceil((hi - lo) / resolution).astype(int)[::-1] + 1
        cells = np.floor((points - lo) / resolution).astype(int)
        empty = np.ones(shape, dtype=bool)
        empty[cells[:, 1], cells[:, 0]] = False
        # the distance from each cell's centre to the exact point of its nearest occupied
        # cell, not to that cell's centre: a wall on a cell border is not moved half a cell
        exact = np.zeros((*shape, 2))
        exact[cells[:, 1], cells[:, 0]] = points
        _, (near_r, near_c) = ndimage.distance_transform_edt(empty, return_indices=True)
        rows, cols = np.indices(shape)
        centre_x = lo[0] + (cols + 0.5) * resolution
        centre_y = lo[1] + (rows + 0.5) * resolution
        nearest = exact[near_r, near_c]
        distance = np.hypot(centre_x - nearest[..., 0], centre_y - nearest[..., 1])
        grid = np.exp(-0.5 * (distance / max(smear, 1e-6)) ** 2).astype(np.float32)
        return cls(grid, lo, resolution)

    def cells(self, points: np.ndarray) -> np.ndarray:
        return np.floor((points - self.origin) / self.resolution).astype(np.int64)

    def bilinear(self, points: np.ndarray) -> np.ndarray:
        """Field values at points (..., 2); 0 outside."""
        u = (points - self.origin) / self.resolution - 0.5
        i0 = np.floor(u).astype(np.int64)
        a = u - i0
        rows, cols = self.grid.shape
        padded = np.pad(self.grid, 1)
        c0 = np.clip(i0[..., 0] + 1, 0, cols)
        r0 = np.clip(i0[..., 1] + 1, 0, rows)
        c1, r1 = np.minimum(c0 + 1, cols + 1), np.minimum(r0 + 1, rows + 1)
        ax, ay = a[..., 0], a[..., 1]
        return ((1 - ax) * (1 - ay) * padded[r0, c0] + ax * (1 - ay) * padded[r0, c1]
                + (1 - ax) * ay * padded[r1, c0] + ax * ay * padded[r1, c1])


def _penalty(dx: np.ndarray, dy: np.ndarray, dtheta: float, p: Penalties) -> np.ndarray:
    distance = np.maximum(1.0 - 0.2 * (dx * dx + dy * dy) / p.distance_variance_penalty,
                          p.minimum_distance_penalty)
    angle = max(1.0 - 0.2 * dtheta * dtheta / p.angle_variance_penalty,
                p.minimum_angle_penalty)
    return distance * angle


def _angles(half: float, step: float) -> np.ndarray:
    count = round(half / step) if step > 0 else 0
    return np.arange(-count, count + 1) * step


def coarse_scores(field: LikelihoodField, points: np.ndarray, prior: np.ndarray,
                  window: SearchWindow, penalties: Penalties
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Scores (angles, 2h+1, 2h+1) of every lattice pose: [a, j, i] is angle a, translation
    (i - h, j - h) cells from the prior; with the angle offsets and the offset in metres."""
    res = field.resolution
    half = max(1, round(window.linear / res))
    offsets = np.arange(-half, half + 1) * res
    angles = _angles(window.angular, window.angular_step)
    rows, cols = field.grid.shape
    padded = np.pad(field.grid, half + 1)
    dx, dy = np.meshgrid(offsets, offsets)
    scores = np.zeros((angles.size, 2 * half + 1, 2 * half + 1))
    n = len(points)
    for k, dtheta in enumerate(angles):
        world = transform(points, np.array([prior[0], prior[1], prior[2] + dtheta]))
        cells = field.cells(world) + half + 1
        inside = ((cells[:, 0] >= half + 1) & (cells[:, 0] < cols + half + 1)
                  & (cells[:, 1] >= half + 1) & (cells[:, 1] < rows + half + 1))
        total = np.zeros((2 * half + 1, 2 * half + 1))
        # one slice of the field per point: the sum over points of the field shifted by
        # every lattice offset at once (a correlation, without building a scan image)
        for c, r in cells[inside]:
            total += padded[r - half:r + half + 1, c - half:c + half + 1]
        scores[k] = total / n * _penalty(dx, dy, float(dtheta), penalties)
    return scores, angles, offsets


def _covariance(scores: np.ndarray, angles: np.ndarray, offsets: np.ndarray,
                best: tuple[int, int, int], window: SearchWindow) -> np.ndarray:
    k, j, i = best
    top = scores[k, j, i]
    plane = scores[k]
    near = plane >= top - 0.1
    dx, dy = np.meshgrid(offsets - offsets[i], offsets - offsets[j])
    w = np.where(near, plane, 0.0)
    norm = max(w.sum(), 1e-12)
    cov = np.zeros((3, 3))
    cov[0, 0] = (w * dx * dx).sum() / norm
    cov[1, 1] = (w * dy * dy).sum() / norm
    cov[0, 1] = cov[1, 0] = (w * dx * dy).sum() / norm
    column = scores[:, j, i]
    wa = np.where(column >= top - 0.1, column, 0.0)
    da = angles - angles[k]
    cov[2, 2] = (wa * da * da).sum() / max(wa.sum(), 1e-12)
    floor_xy = (0.5 * window.resolution) ** 2
    cov[0, 0] = max(cov[0, 0], floor_xy)
    cov[1, 1] = max(cov[1, 1], floor_xy)
    cov[2, 2] = max(cov[2, 2], (0.5 * window.angular_step) ** 2)
    return cov


def refine(field: LikelihoodField, points: np.ndarray, center: np.ndarray,
           prior: np.ndarray, window: SearchWindow, penalties: Penalties
           ) -> tuple[np.ndarray, float]:
    """The fine search: a cell around `center` in quarter cells (the coarse lattice reads
    the nearest cell, so its best can be a cell off), half a coarse angle step in fine angle
    steps; bilinear field values."""
    res = field.resolution
    offsets = np.arange(-4, 5) * (res / 4)
    angles = _angles(0.5 * window.angular_step, window.fine_angular_step)
    dx, dy = (a.ravel() for a in np.meshgrid(offsets, offsets))
    best, best_score = center, -1.0
    for dtheta in angles:
        theta = center[2] + dtheta
        base = transform(points, np.array([center[0], center[1], theta]))
        world = base[None, :, :] + np.stack([dx, dy], axis=1)[:, None, :]
        score = field.bilinear(world).mean(axis=1)
        score *= _penalty(center[0] + dx - prior[0], center[1] + dy - prior[1],
                          float(theta - prior[2]), penalties)
        k = int(np.argmax(score))
        if score[k] > best_score:
            best_score = float(score[k])
            best = np.array([center[0] + dx[k], center[1] + dy[k], theta])
    return best, best_score


def match(field: LikelihoodField, points: np.ndarray, prior: np.ndarray,
          window: SearchWindow, penalties: Penalties = Penalties(),
          fine: bool = True) -> Match:
    """The best pose of the scan `points` (N, 2, robot frame) in the field, near `prior`."""
    scores, angles, offsets = coarse_scores(field, points, prior, window, penalties)
    best = np.unravel_index(int(np.argmax(scores)), scores.shape)
    k, j, i = (int(v) for v in best)
    pose = np.array([prior[0] + offsets[i], prior[1] + offsets[j], prior[2] + angles[k]])
    response = float(scores[k, j, i])
    cov = _covariance(scores, angles, offsets, (k, j, i), window)
    if fine:
        pose, response = refine(field, points, pose, prior, window, penalties)
    pose[2] = math.atan2(math.sin(pose[2]), math.cos(pose[2]))
    return Match(pose, response, cov)


def decimate(points: np.ndarray, count: int) -> np.ndarray:
    """At most `count` of the points, evenly spread over the scan."""
    if len(points) <= count:
        return points
    return points[np.linspace(0, len(points) - 1, count).astype(int)]
