"""quaternion_from_euler as the tf2 pages define it, without numpy or tf_transformations."""

from __future__ import annotations

import math


def quaternion_from_euler(roll: float, pitch: float, yaw: float
                          ) -> tuple[float, float, float, float]:
    """(x, y, z, w) of the rotation by roll about x, then pitch about y, then yaw about z."""
    cr, sr = math.cos(roll / 2.0), math.sin(roll / 2.0)
    cp, sp = math.cos(pitch / 2.0), math.sin(pitch / 2.0)
    cy, sy = math.cos(yaw / 2.0), math.sin(yaw / 2.0)
    return (sr * cp * cy - cr * sp * sy,
            cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy,
            cr * cp * cy + sr * sp * sy)
