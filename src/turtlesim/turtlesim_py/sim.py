"""Pure simulation maths of turtlesim, free of ROS and Qt so tests can call it directly.

Coordinates follow upstream: x to the right in metres; `y_int` is measured *downwards* from
the top of the canvas (as upstream stores it), world y = CANVAS_HEIGHT - y_int.
"""

from __future__ import annotations

import math
import struct
from dataclasses import dataclass

PIXELS_PER_METER = 45.0
CANVAS_PIXELS = 500
# Upstream computes (500 - 1) / 45 in float32.
CANVAS_WIDTH = struct.unpack('f', struct.pack('f', (CANVAS_PIXELS - 1) / PIXELS_PER_METER))[0]
CANVAS_HEIGHT = CANVAS_WIDTH
CENTER = CANVAS_WIDTH / 2.0
UPSTREAM_PI = 3.14159265
FIXED_DT = 0.016
CMD_VEL_TIMEOUT = 1.0
ROTATION_TOLERANCE = 0.02
ROTATION_SPEED = 1.0
FLOAT32_MAX = 3.4028234663852886e38


def norm_angle(angle: float) -> float:
    """Wrap into [-pi, pi) exactly as upstream: a - 2pi * floor((a + pi) / 2pi)."""
    two_pi = 2.0 * UPSTREAM_PI
    if abs(angle) > 1e9:
        # The formula loses every digit for huge angles (theta + 3e38 rad/s * dt ended as
        # -5.9e20, found by fuzzing); fmod is exact, and the same within float precision.
        angle = math.fmod(angle, two_pi)
    return angle - two_pi * math.floor((angle + UPSTREAM_PI) / two_pi)


def integrate(x: float, y_int: float, theta: float, vx: float, vy: float, w: float,
              dt: float) -> tuple[float, float, float]:
    """Semi-implicit Euler: the heading is updated first and the move uses the new heading."""
    theta = norm_angle(theta + w * dt)
    cos_t = math.cos(theta)
    sin_t = math.sin(theta)
    x += (vx * cos_t - vy * sin_t) * dt
    y_int -= (vx * sin_t + vy * cos_t) * dt
    return x, y_int, theta


def hits_wall(x: float, y_int: float) -> bool:
    return x < 0.0 or x > CANVAS_WIDTH or y_int < 0.0 or y_int > CANVAS_HEIGHT


def clamp_to_walls(x: float, y_int: float) -> tuple[float, float]:
    return min(max(x, 0.0), CANVAS_WIDTH), min(max(y_int, 0.0), CANVAS_HEIGHT)


def wall_warning(x: float, y_int: float) -> str:
    """The upstream warning text, with the internal (downward) y."""
    return f'Oh no! I hit the wall! (Clamping from [x={x:f}, y={y_int:f}])'


def teleport_relative(x: float, y_int: float, theta: float, linear: float,
                      angular: float) -> tuple[float, float, float]:
    """Rotate first, then move `linear` along the new heading; theta is not normalised."""
    theta += angular
    x += math.cos(theta) * linear
    y_int -= math.sin(theta) * linear
    return x, y_int, theta


def teleport_absolute(x: float, y: float, theta: float) -> tuple[float, float, float]:
    """World (x, y, theta) to internal; y above the top is silently clamped as upstream."""
    return x, max(0.0, CANVAS_HEIGHT - y), theta


def to_pixel(x: float, y_int: float) -> tuple[int, int]:
    """Path-image pixel under a position (round(pos * 45)), kept inside the image."""
    last = CANVAS_PIXELS - 1
    px = min(max(round(x * PIXELS_PER_METER), 0), last)
    py = min(max(round(y_int * PIXELS_PER_METER), 0), last)
    return px, py


@dataclass(frozen=True)
class RotateStep:
    done: bool
    remaining: float
    delta: float
    angular_velocity: float


def rotate_step(theta: float, goal_theta: float, start_theta: float) -> RotateStep:
    """One tick of rotate_absolute: feedback, result delta, completion and the command."""
    target = norm_angle(goal_theta)
    remaining = norm_angle(target - theta)
    delta = norm_angle(start_theta - theta)
    done = abs(norm_angle(theta - target)) < ROTATION_TOLERANCE
    speed = 0.0 if done else (ROTATION_SPEED if remaining >= 0.0 else -ROTATION_SPEED)
    return RotateStep(done, remaining, delta, speed)


def pose_linear_velocity(vx: float, vy: float) -> float:
    return math.hypot(vx, vy)


def finite_float32(value: float) -> bool:
    """True for finite values a float32 field can carry."""
    return math.isfinite(value) and abs(value) <= FLOAT32_MAX
