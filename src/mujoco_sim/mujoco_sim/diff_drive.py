"""Differential drive: /cmd_vel to wheel speeds, and odometry from the wheels' turning.

As a diff-drive controller does: a Twist's linear.x and angular.z give each wheel's speed
from the wheel radius and separation; odometry integrates the wheels' measured rotation
(not the simulator's ground truth), so wheel slip shows as odometry drift, as on a robot.
"""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True)
class WheelGeometry:
    radius: float  # m
    separation: float  # m between the wheels' contact points


def check_twist(linear: float, angular: float, max_linear: float,
                max_angular: float) -> tuple[float, float, str | None]:
    """The command to apply and, when it was changed, one line saying why.

    Non-finite values are refused (the robot stops); values beyond the limits are clamped.
    """
    for field, value in (('linear.x', linear), ('angular.z', angular)):
        if not math.isfinite(value):
            return 0.0, 0.0, (f'ignoring /cmd_vel: {field} is {value}; allowed: finite '
                              'numbers (the robot stops)')
    clamped_linear = max(-max_linear, min(max_linear, linear))
    clamped_angular = max(-max_angular, min(max_angular, angular))
    if (clamped_linear, clamped_angular) != (linear, angular):
        return clamped_linear, clamped_angular, (
            f'clamping /cmd_vel (linear.x {linear:g}, angular.z {angular:g}) to the limits '
            f'|linear.x| <= {max_linear:g} m/s, |angular.z| <= {max_angular:g} rad/s')
    return linear, angular, None


def wheel_speeds(geometry: WheelGeometry, linear: float,
                 angular: float) -> tuple[float, float]:
    """Left and right wheel angular velocities (rad/s) for a body twist."""
    half = geometry.separation / 2
    return ((linear - angular * half) / geometry.radius,
            (linear + angular * half) / geometry.radius)


class Odometry:
    """Pose of the base in the odom frame from the wheels' angles (midpoint integration)."""

    def __init__(self, geometry: WheelGeometry) -> None:
        self.geometry = geometry
        self.reset()

    def reset(self, left: float | None = None, right: float | None = None) -> None:
        self.x = self.y = self.yaw = 0.0
        self.linear = self.angular = 0.0
        self._last = None if left is None else (left, right)

    def update(self, left: float, right: float, dt: float) -> None:
        """Advance with the wheels' new angles (rad) after `dt` seconds."""
        if self._last is None:
            self._last = (left, right)
            return
        r = self.geometry.radius
        d_left, d_right = (left - self._last[0]) * r, (right - self._last[1]) * r
        self._last = (left, right)
        distance = (d_left + d_right) / 2
        turn = (d_right - d_left) / self.geometry.separation
        heading = self.yaw + turn / 2
        self.x += distance * math.cos(heading)
        self.y += distance * math.sin(heading)
        self.yaw = math.atan2(math.sin(self.yaw + turn), math.cos(self.yaw + turn))
        if dt > 0:
            self.linear, self.angular = distance / dt, turn / dt
