"""Rigid-transform maths on plain tuples: (x, y, z) vectors and (x, y, z, w) quaternions.

Plain floats, not numpy: for 3- and 4-element values Python arithmetic is several times
faster than numpy's per-call overhead, and lookups are dominated by these few operations.
"""
import math

Vector = tuple[float, float, float]
Quaternion = tuple[float, float, float, float]
Transform = tuple[float, float, float, float, float, float, float]  # x y z qx qy qz qw

IDENTITY: Transform = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0)


def multiply(a: Quaternion, b: Quaternion) -> Quaternion:
    """Hamilton product a * b (rotate by b, then by a)."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz)


def rotate(q: Quaternion, v: Vector) -> Vector:
    """The vector v rotated by the unit quaternion q."""
    qx, qy, qz, qw = q
    vx, vy, vz = v
    # t = 2 q.xyz x v;  v' = v + w t + q.xyz x t
    tx = 2.0 * (qy * vz - qz * vy)
    ty = 2.0 * (qz * vx - qx * vz)
    tz = 2.0 * (qx * vy - qy * vx)
    return (vx + qw * tx + qy * tz - qz * ty,
            vy + qw * ty + qz * tx - qx * tz,
            vz + qw * tz + qx * ty - qy * tx)


def compose(a: Transform, b: Transform) -> Transform:
    """a * b: b's frame expressed through a (apply b, then a)."""
    x, y, z = rotate(a[3:], b[:3])
    qx, qy, qz, qw = multiply(a[3:], b[3:])
    return (x + a[0], y + a[1], z + a[2], qx, qy, qz, qw)


def inverse(t: Transform) -> Transform:
    conjugate = (-t[3], -t[4], -t[5], t[6])
    x, y, z = rotate(conjugate, (-t[0], -t[1], -t[2]))
    return (x, y, z, *conjugate)


def slerp(a: Quaternion, b: Quaternion, ratio: float) -> Quaternion:
    """Spherical interpolation along the shortest path, as tf2's (Bullet's) slerp."""
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    dot = ax * bx + ay * by + az * bz + aw * bw
    if dot < 0.0:  # the long way round: interpolate towards -b, the same rotation
        bx, by, bz, bw, dot = -bx, -by, -bz, -bw, -dot
    norm = math.sqrt((ax * ax + ay * ay + az * az + aw * aw)
                     * (bx * bx + by * by + bz * bz + bw * bw))
    theta = math.acos(min(dot / norm, 1.0)) if norm else 0.0
    if theta < 1e-9:
        return a
    scale = 1.0 / math.sin(theta)
    s0 = math.sin((1.0 - ratio) * theta) * scale
    s1 = math.sin(ratio * theta) * scale
    return (ax * s0 + bx * s1, ay * s0 + by * s1, az * s0 + bz * s1, aw * s0 + bw * s1)


def quaternion_from_euler(roll: float, pitch: float, yaw: float) -> Quaternion:
    """(x, y, z, w) of the fixed-axis roll (x), pitch (y), yaw (z) rotation, as tf2's setRPY."""
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (sr * cp * cy - cr * sp * sy,
            cr * sp * cy + sr * cp * sy,
            cr * cp * sy - sr * sp * cy,
            cr * cp * cy + sr * sp * sy)


def euler_from_quaternion(q: Quaternion) -> tuple[float, float, float]:
    """(roll, pitch, yaw) of a unit quaternion, as tf2's Matrix3x3::getRPY."""
    x, y, z, w = q
    sin_pitch = 2.0 * (w * y - z * x)
    pitch = math.copysign(math.pi / 2, sin_pitch) if abs(sin_pitch) >= 1.0 else math.asin(sin_pitch)
    roll = math.atan2(2.0 * (w * x + y * z), 1.0 - 2.0 * (x * x + y * y))
    yaw = math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))
    return roll, pitch, yaw
