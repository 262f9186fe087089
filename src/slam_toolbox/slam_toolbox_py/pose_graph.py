"""The pose graph and its optimiser: scipy.optimize.least_squares with a sparse Jacobian.

Nodes are 2D poses (x, y, theta). An edge (i, j, z, information) says "node j seen from node
i is at z"; its residual is S (h(x_i, x_j) - z) with h the pose of j in i's frame and S the
Cholesky factor of the information (S^T S = information), the angle wrapped into (-pi, pi].
The first node is held fixed (the map frame's anchor). The Jacobian is analytic and sparse:
each edge touches six variables, so a graph of a thousand nodes is a few milliseconds of
trust-region steps (method 'trf' with the LSMR solver).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import sparse
from scipy.optimize import least_squares


def wrap(angle: np.ndarray | float) -> np.ndarray | float:
    return np.arctan2(np.sin(angle), np.cos(angle))


def relative(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Pose b in the frame of pose a."""
    c, s = math.cos(a[2]), math.sin(a[2])
    dx, dy = b[0] - a[0], b[1] - a[1]
    return np.array([c * dx + s * dy, -s * dx + c * dy, float(wrap(b[2] - a[2]))])


def compose(a: np.ndarray, z: np.ndarray) -> np.ndarray:
    """The pose at z in the frame of pose a."""
    c, s = math.cos(a[2]), math.sin(a[2])
    return np.array([a[0] + c * z[0] - s * z[1], a[1] + s * z[0] + c * z[1],
                     float(wrap(a[2] + z[2]))])


@dataclass
class Edge:
    i: int
    j: int
    z: np.ndarray  # pose of j in i's frame
    information: np.ndarray  # 3 x 3
    loop: bool = False  # a loop closure (drawn apart in the graph visualisation)


def _residuals_and_jacobian(poses: np.ndarray, edges: list[Edge]
                            ) -> tuple[np.ndarray, sparse.csr_matrix]:
    m = len(edges)
    i = np.array([e.i for e in edges])
    j = np.array([e.j for e in edges])
    z = np.array([e.z for e in edges])
    roots = np.array([np.linalg.cholesky(e.information).T for e in edges])  # S, upper
    pi, pj = poses[i], poses[j]
    c, s = np.cos(pi[:, 2]), np.sin(pi[:, 2])
    dx, dy = pj[:, 0] - pi[:, 0], pj[:, 1] - pi[:, 1]
    error = np.stack([c * dx + s * dy - z[:, 0], -s * dx + c * dy - z[:, 1],
                      wrap(pj[:, 2] - pi[:, 2] - z[:, 2])], axis=1)
    residuals = np.einsum('mab,mb->ma', roots, error).ravel()
    # d error / d (x_i, y_i, th_i, x_j, y_j, th_j), one 3 x 6 block per edge
    blocks = np.zeros((m, 3, 6))
    blocks[:, 0, 0], blocks[:, 0, 1] = -c, -s
    blocks[:, 1, 0], blocks[:, 1, 1] = s, -c
    blocks[:, 0, 2] = -s * dx + c * dy
    blocks[:, 1, 2] = -c * dx - s * dy
    blocks[:, 2, 2] = -1.0
    blocks[:, 0, 3], blocks[:, 0, 4] = c, s
    blocks[:, 1, 3], blocks[:, 1, 4] = -s, c
    blocks[:, 2, 5] = 1.0
    blocks = np.einsum('mab,mbc->mac', roots, blocks)
    rows = np.repeat(np.arange(3 * m).reshape(m, 3, 1), 6, axis=2)
    cols = np.concatenate([3 * i[:, None] + np.arange(3), 3 * j[:, None] + np.arange(3)],
                          axis=1)[:, None, :].repeat(3, axis=1)
    jac = sparse.csr_matrix((blocks.ravel(), (rows.ravel(), cols.ravel())),
                            shape=(3 * m, 3 * len(poses)))
    return residuals, jac


def optimize(poses: np.ndarray, edges: list[Edge], fixed: int = 0,
             max_iterations: int = 50) -> np.ndarray:
    """The poses (n, 3) that best agree with the edges, node `fixed` held where it is."""
    n = len(poses)
    if n < 2 or not edges:
        return poses.copy()
    free = np.ones(3 * n, dtype=bool)
    free[3 * fixed:3 * fixed + 3] = False
    anchor = poses.copy()

    def full(x: np.ndarray) -> np.ndarray:
        values = anchor.ravel().copy()
        values[free] = x
        return values.reshape(n, 3)

    def fun(x: np.ndarray) -> np.ndarray:
        return _residuals_and_jacobian(full(x), edges)[0]

    def jac(x: np.ndarray) -> sparse.csr_matrix:
        return _residuals_and_jacobian(full(x), edges)[1][:, free]

    result = least_squares(fun, anchor.ravel()[free], jac=jac, method='trf',
                           tr_solver='lsmr', x_scale='jac', max_nfev=max_iterations,
                           xtol=1e-10, ftol=1e-10, gtol=1e-10)
    out = full(result.x)
    out[:, 2] = wrap(out[:, 2])
    return out


def information_from_covariance(covariance: np.ndarray) -> np.ndarray:
    cov = 0.5 * (covariance + covariance.T) + np.eye(3) * 1e-9
    return np.linalg.inv(cov)
