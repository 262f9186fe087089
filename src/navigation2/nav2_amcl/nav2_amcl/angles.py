"""AMCL's angle helpers (`angleutils.cpp`)."""

from __future__ import annotations

import numpy as np


def normalize(z: np.ndarray | float) -> np.ndarray:
    """Angle in (-pi, pi], as atan2(sin z, cos z)."""
    return np.arctan2(np.sin(z), np.cos(z))


def angle_diff(a: np.ndarray | float, b: np.ndarray | float) -> np.ndarray:
    """a - b as the shorter of the two ways round (upstream's angle_diff)."""
    a = normalize(a)
    b = normalize(b)
    d1 = a - b
    d2 = 2 * np.pi - np.abs(d1)
    d2 = np.where(d1 > 0, -d2, d2)
    return np.where(np.abs(d1) < np.abs(d2), d1, d2)
