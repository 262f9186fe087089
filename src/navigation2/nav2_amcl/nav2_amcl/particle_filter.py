"""AMCL's particle filter (`pf.c`, `pf_kdtree.c`): KLD sampling, recovery, clusters.

One sample set of poses (N x 3: x, y, yaw) and weights. The sensor update multiplies the
weights by the laser model's factors and tracks the short- and long-term average weight
(w_fast, w_slow); resampling draws by weight, replaces a share 1 - w_fast / w_slow of the
draws by random poses (recovery), and stops when the set's histogram of (x, y, yaw) bins has
enough samples for the KLD bound of pf_err / pf_z (Fox 2003) - done for all draws at once.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np

# pf_kdtree's bin sizes: 0.5 m, 0.5 m, 10 degrees.
BIN_SIZE = np.array([0.5, 0.5, np.deg2rad(10.0)])
# pf_update_converged: every sample within this of the mean in x and in y.
DIST_THRESHOLD = 0.5

PoseGenerator = Callable[[int], np.ndarray]  # count -> count x 3 poses


@dataclass
class Cluster:
    """A set of neighbouring histogram bins: its weight, mean pose and covariance."""

    weight: float
    mean: np.ndarray
    cov: np.ndarray


def resample_limit(k: np.ndarray | int, min_samples: int, max_samples: int, pop_err: float,
                   pop_z: float) -> np.ndarray:
    """pf_resample_limit: the KLD sample count for k occupied bins (vectorised over k)."""
    k = np.asarray(k, dtype=np.float64)
    km1 = np.maximum(k - 1.0, 1.0)
    b = 2.0 / (9.0 * km1)
    x = 1.0 - b + np.sqrt(b) * pop_z
    n = np.ceil(km1 / (2.0 * pop_err) * x ** 3)
    n = np.clip(n, min_samples, max_samples)
    return np.where(k <= 1, max_samples, n).astype(np.int64)


def bin_keys(poses: np.ndarray) -> np.ndarray:
    """The histogram bin of each pose (yaw as it is, not wrapped: as pf_kdtree)."""
    return np.floor(poses / BIN_SIZE).astype(np.int64)


def _key_ids(keys: np.ndarray) -> np.ndarray:
    """One integer per distinct bin (keys shifted to start at 0 and mixed radix)."""
    shifted = keys - keys.min(axis=0)
    span = shifted.max(axis=0) + 1
    return (shifted[:, 0] * span[1] + shifted[:, 1]) * span[2] + shifted[:, 2]


def cluster_labels(poses: np.ndarray) -> np.ndarray:
    """pf_kdtree_cluster: bins touching in any of the 26 directions form one cluster."""
    keys = bin_keys(poses)
    unique, inverse = np.unique(keys, axis=0, return_inverse=True)
    index = {tuple(key): i for i, key in enumerate(unique.tolist())}
    parent = list(range(len(unique)))

    def root(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    offsets = [(a, b, c) for a in (-1, 0, 1) for b in (-1, 0, 1) for c in (-1, 0, 1)]
    for i, (kx, ky, kt) in enumerate(unique.tolist()):
        for a, b, c in offsets:
            j = index.get((kx + a, ky + b, kt + c))
            if j is not None:
                ri, rj = root(i), root(j)
                if ri != rj:
                    parent[rj] = ri
    roots = np.array([root(i) for i in range(len(unique))])
    _, labels = np.unique(roots, return_inverse=True)
    return labels[np.asarray(inverse).ravel()]


def weighted_stats(poses: np.ndarray, weights: np.ndarray) -> tuple[float, np.ndarray,
                                                                     np.ndarray]:
    """pf_update_cluster_stats for one group: weight, mean (circular yaw) and covariance.

    The yaw variance is -2 ln(R) of the weighted mean resultant length R (normalised by the
    group's weight, the fix of ros-planning/navigation#1160).
    """
    total = float(weights.sum())
    mean = np.zeros(3)
    cov = np.zeros((3, 3))
    if total <= 0:
        return total, mean, cov
    mean[:2] = weights @ poses[:, :2] / total
    cos_sum = float(weights @ np.cos(poses[:, 2]))
    sin_sum = float(weights @ np.sin(poses[:, 2]))
    mean[2] = np.arctan2(sin_sum, cos_sum)
    xy = poses[:, :2]
    cov[:2, :2] = (xy * weights[:, None]).T @ xy / total - np.outer(mean[:2], mean[:2])
    resultant = min(np.hypot(cos_sum, sin_sum) / total, 1.0)
    cov[2, 2] = -2.0 * np.log(resultant) if resultant > 0 else np.inf
    return total, mean, cov


@dataclass
class ParticleFilter:
    """pf_t: sample limits, KLD parameters and the recovery filter state."""

    min_samples: int = 500
    max_samples: int = 2000
    pop_err: float = 0.05  # pf_err
    pop_z: float = 0.99  # pf_z
    alpha_slow: float = 0.0  # recovery_alpha_slow
    alpha_fast: float = 0.0  # recovery_alpha_fast
    rng: np.random.Generator = field(default_factory=np.random.default_rng)
    random_pose: PoseGenerator | None = None
    poses: np.ndarray = field(default_factory=lambda: np.zeros((0, 3)))
    weights: np.ndarray = field(default_factory=lambda: np.zeros(0))
    w_slow: float = 0.0
    w_fast: float = 0.0
    n_effective: float = 0.0
    converged: bool = False
    clusters: list[Cluster] = field(default_factory=list)
    mean: np.ndarray = field(default_factory=lambda: np.zeros(3))
    cov: np.ndarray = field(default_factory=lambda: np.zeros((3, 3)))

    def __post_init__(self) -> None:
        if not 0 < self.min_samples <= self.max_samples:
            raise ValueError(f'min_particles: {self.min_samples} must be > 0 and <= '
                             f'max_particles ({self.max_samples})')

    @property
    def sample_count(self) -> int:
        return int(self.poses.shape[0])

    def init_gaussian(self, mean: np.ndarray, cov: np.ndarray) -> None:
        """pf_init: max_samples poses from a Gaussian (set_initial_pose, /initialpose)."""
        values, vectors = np.linalg.eigh(np.asarray(cov, dtype=np.float64))
        scale = np.sqrt(np.clip(values, 0.0, None))
        draws = self.rng.standard_normal((self.max_samples, 3)) * scale
        self._reset(np.asarray(mean, dtype=np.float64) + draws @ vectors.T)

    def init_model(self, generator: PoseGenerator) -> None:
        """pf_init_model: max_samples poses from a generator (global localisation)."""
        self._reset(np.asarray(generator(self.max_samples), dtype=np.float64))

    def _reset(self, poses: np.ndarray) -> None:
        self.poses = poses
        self.weights = np.full(poses.shape[0], 1.0 / poses.shape[0])
        self.w_slow = self.w_fast = 0.0
        self.update_cluster_stats()
        self.update_converged()

    def update_sensor(self, factors: np.ndarray) -> None:
        """pf_update_sensor: weights *= the model's factors, normalised; w_slow/w_fast."""
        weights = self.weights * factors
        total = float(weights.sum())
        if total > 0 and np.isfinite(total):
            w_avg = total / weights.size
            self.weights = weights / total
            if self.w_slow == 0.0:
                self.w_slow = w_avg
            else:
                self.w_slow += self.alpha_slow * (w_avg - self.w_slow)
            if self.w_fast == 0.0:
                self.w_fast = w_avg
            else:
                self.w_fast += self.alpha_fast * (w_avg - self.w_fast)
        else:
            self.weights = np.full(weights.size, 1.0 / weights.size)
        self.n_effective = 1.0 / float(np.sum(self.weights ** 2))

    def resample(self) -> None:
        """pf_update_resample: draw by weight with KLD-limited count and random recovery."""
        w_diff = 0.0
        if self.w_slow > 0:
            w_diff = max(1.0 - self.w_fast / self.w_slow, 0.0)
        cumulative = np.cumsum(self.weights)
        cumulative /= cumulative[-1]
        picks = np.searchsorted(cumulative, self.rng.random(self.max_samples), side='right')
        drawn = self.poses[np.minimum(picks, self.sample_count - 1)].copy()
        if w_diff > 0 and self.random_pose is not None:
            randoms = self.rng.random(self.max_samples) < w_diff
            if randoms.any():
                drawn[randoms] = self.random_pose(int(randoms.sum()))
        count = self._kld_count(drawn)
        if w_diff > 0:
            self.w_slow = self.w_fast = 0.0
        self.poses = drawn[:count]
        self.weights = np.full(count, 1.0 / count)
        self.update_cluster_stats()
        self.update_converged()

    def _kld_count(self, drawn: np.ndarray) -> int:
        """Samples kept: the first n with n > pf_resample_limit(bins among the first n)."""
        ids = _key_ids(bin_keys(drawn))
        _, first = np.unique(ids, return_index=True)
        new_bin = np.zeros(ids.size, dtype=np.int64)
        new_bin[first] = 1
        bins = np.cumsum(new_bin)
        limits = resample_limit(bins, self.min_samples, self.max_samples, self.pop_err,
                                self.pop_z)
        counts = np.arange(1, ids.size + 1)
        over = np.nonzero(counts > limits)[0]
        return int(over[0] + 1) if over.size else int(ids.size)

    def update_cluster_stats(self) -> None:
        """Clusters of neighbouring bins with their statistics, and the whole set's."""
        _, self.mean, self.cov = weighted_stats(self.poses, self.weights)
        labels = cluster_labels(self.poses)
        self.clusters = []
        for label in range(int(labels.max(initial=-1)) + 1):
            members = labels == label
            weight, mean, cov = weighted_stats(self.poses[members], self.weights[members])
            self.clusters.append(Cluster(weight, mean, cov))

    def update_converged(self) -> None:
        """pf_update_converged: all samples within DIST_THRESHOLD of the mean in x and y."""
        offsets = np.abs(self.poses[:, :2] - self.mean[:2])
        self.converged = bool(np.all(offsets <= DIST_THRESHOLD))

    def best_cluster(self) -> Cluster | None:
        """The hypothesis amcl publishes: the cluster of the largest total weight."""
        if not self.clusters:
            return None
        return max(self.clusters, key=lambda cluster: cluster.weight)
