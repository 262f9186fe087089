"""tf2's lookupVelocity: the twist of one frame seen from another, from two lookups an
averaging interval apart (BufferCore.lookupVelocityCore / lookupVelocityFullCore)."""

from __future__ import annotations

import math
from collections.abc import Callable

from tf2_py.maths import Quaternion, Transform, Vector, multiply, rotate

Lookup = Callable[[str, str, int], Transform]  # (target, source, time in ns) -> transform
Twist = tuple[Vector, Vector]


def _seconds_to_ns(seconds: float) -> int:
    return round(seconds * 1e9)


def _axis_angle(q: Quaternion) -> tuple[Vector, float]:
    """As tf2's Quaternion getAxis/getAngle: no defined axis for no rotation gives x."""
    x, y, z, w = q
    w = max(-1.0, min(1.0, w))
    s_squared = 1.0 - w * w
    axis = (1.0, 0.0, 0.0) if s_squared < 10.0 * 2.220446049250313e-16 else \
        tuple(c / math.sqrt(s_squared) for c in (x, y, z))
    return axis, 2.0 * math.acos(w)


def _cross(a: Vector, b: Vector) -> Vector:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _apply(t: Transform, point: Vector) -> Vector:
    x, y, z = rotate(t[3:], point)
    return x + t[0], y + t[1], z + t[2]


def lookup_velocity(lookup: Lookup, latest_ns: int, tracking: str, observation: str,
                    reference: str, reference_point: Vector, reference_point_frame: str,
                    time_ns: int, interval_ns: int) -> Twist:
    """(linear, angular) velocity of `tracking` relative to `observation`, expressed in
    `reference` about `reference_point` (given in `reference_point_frame`), averaged over
    `interval_ns` centred on `time_ns` (0: latest) and clipped to the newest data."""
    time_s, interval_s = time_ns / 1e9, interval_ns / 1e9
    end = min(time_s + interval_s * 0.5, latest_ns / 1e9)
    start = max(0.00001 + interval_s, end) - interval_s
    elapsed = end - start  # shorter than the interval when the start was clipped at 0
    first = lookup(observation, tracking, _seconds_to_ns(start))
    last = lookup(observation, tracking, _seconds_to_ns(end))

    conjugate = (-first[3], -first[4], -first[5], first[6])
    axis, angle = _axis_angle(multiply(conjugate, last[3:]))
    turn = rotate(first[3:], axis)
    linear = tuple((last[i] - first[i]) / elapsed for i in range(3))
    angular = tuple(c * angle / elapsed for c in turn)

    in_reference = lookup(reference, tracking, time_ns)
    out_angular = rotate(in_reference[3:], angular)
    moved = rotate(in_reference[3:], linear)
    lever = _cross(in_reference[:3], out_angular)
    out_linear = tuple(moved[i] + lever[i] for i in range(3))

    origin = _apply(in_reference, (0.0, 0.0, 0.0))
    desired = _apply(lookup(reference, reference_point_frame, time_ns), reference_point)
    # tf2 re-references with Vector3's `*`, which multiplies component by component.
    out_linear = tuple(out_linear[i] + out_angular[i] * (desired[i] - origin[i])
                       for i in range(3))
    return out_linear, out_angular
