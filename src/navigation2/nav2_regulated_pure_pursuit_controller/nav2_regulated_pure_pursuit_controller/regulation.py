"""Regulated Pure Pursuit's maths as plain functions (upstream's regulation_functions.hpp and
the geometric helpers of RegulatedPurePursuitController), on plans in the robot's frame:
(N, 3) arrays of x, y, yaw with the robot at the origin facing +x.
"""

from __future__ import annotations

import math

import numpy as np
from nav2_costmap_2d.cost_values import FREE_SPACE, NO_INFORMATION


def curvature(x: float, y: float) -> float:
    """calculateCurvature: 2 y / d^2 of the carrot (0 when it is within ~3 cm)."""
    dist2 = x * x + y * y
    return 2.0 * y / dist2 if dist2 > 0.001 else 0.0


def lookahead_distance(speed_x: float, lookahead_dist: float, velocity_scaled: bool,
                       lookahead_time: float, min_dist: float, max_dist: float) -> float:
    """getLookAheadDistance: fixed, or |v| * lookahead_time clamped to [min, max]."""
    if not velocity_scaled:
        return lookahead_dist
    return min(max(abs(speed_x) * lookahead_time, min_dist), max_dist)


def circle_segment_intersection(p1: tuple[float, float], p2: tuple[float, float], r: float
                                ) -> tuple[float, float]:
    """The point on segment p1-p2 at distance r from the origin (p1 inside, p2 outside)."""
    (x1, y1), (x2, y2) = p1, p2
    dx, dy = x2 - x1, y2 - y1
    dr2 = dx * dx + dy * dy
    d = x1 * y2 - x2 * y1
    sign = math.copysign(1.0, (x2 * x2 + y2 * y2) - (x1 * x1 + y1 * y1))
    root = math.sqrt(max(r * r * dr2 - d * d, 0.0))
    return ((d * dy + sign * dx * root) / dr2, (-d * dx + sign * dy * root) / dr2)


def lookahead_point(lookahead: float, plan: np.ndarray, interpolate_after_goal: bool = False
                    ) -> tuple[float, float, float]:
    """getLookAheadPoint: the point of the plan at `lookahead` from the robot (interpolated on
    the segment that crosses the circle), or the last pose when none is that far."""
    dist = np.hypot(plan[:, 0], plan[:, 1])
    beyond = np.nonzero(dist >= lookahead)[0]
    if len(beyond) == 0:
        last = plan[-1]
        if interpolate_after_goal and len(plan) > 1:
            prev = plan[-2]
            heading = math.atan2(last[1] - prev[1], last[0] - prev[0])
            far = (last[0] + math.cos(heading) * lookahead, last[1] + math.sin(heading) * lookahead)
            x, y = circle_segment_intersection((last[0], last[1]), far, lookahead)
            return x, y, float(last[2])
        return float(last[0]), float(last[1]), float(last[2])
    i = int(beyond[0])
    if i == 0:
        return float(plan[0, 0]), float(plan[0, 1]), float(plan[0, 2])
    x, y = circle_segment_intersection((plan[i - 1, 0], plan[i - 1, 1]),
                                       (plan[i, 0], plan[i, 1]), lookahead)
    return x, y, float(plan[i, 2])


def curvature_constraint(raw_linear_vel: float, curv: float, min_radius: float) -> float:
    """heuristics::curvatureConstraint: slower on turns tighter than min_radius."""
    radius = abs(1.0 / curv) if curv != 0.0 else math.inf
    if radius < min_radius:
        return raw_linear_vel * (1.0 - abs(radius - min_radius) / min_radius)
    return raw_linear_vel


def cost_constraint(raw_linear_vel: float, pose_cost: float, inscribed_radius: float,
                    inflation_cost_scaling_factor: float, cost_scaling_dist: float,
                    cost_scaling_gain: float) -> float:
    """heuristics::costConstraint: slower near obstacles, by the distance the inflation cost
    under the robot implies."""
    if pose_cost in (float(NO_INFORMATION), float(FREE_SPACE)):
        return raw_linear_vel
    k = inflation_cost_scaling_factor
    min_distance = (k * inscribed_radius - math.log(pose_cost) + math.log(253.0)) / k
    if min_distance < cost_scaling_dist:
        return raw_linear_vel * (cost_scaling_gain * min_distance / cost_scaling_dist)
    return raw_linear_vel


def path_length(plan: np.ndarray) -> float:
    return float(np.hypot(np.diff(plan[:, 0]), np.diff(plan[:, 1])).sum()) \
        if len(plan) > 1 else 0.0


def approach_velocity_scaling_factor(plan: np.ndarray, scaling_dist: float) -> float:
    """heuristics::approachVelocityScalingFactor: distance to the goal over scaling_dist,
    once the rest of the plan is shorter than scaling_dist."""
    if path_length(plan) < scaling_dist:
        return math.hypot(plan[-1, 0], plan[-1, 1]) / scaling_dist
    return 1.0


def approach_velocity_constraint(constrained_vel: float, plan: np.ndarray, min_approach_vel: float,
                                 scaling_dist: float) -> float:
    """heuristics::approachVelocityConstraint."""
    approach = constrained_vel * approach_velocity_scaling_factor(plan, scaling_dist)
    return min(constrained_vel, max(approach, min_approach_vel))


def find_velocity_sign_change(plan: np.ndarray) -> float:
    """findVelocitySignChange: distance to the first cusp of the plan (inf without one)."""
    for i in range(1, len(plan) - 1):
        oa = plan[i, :2] - plan[i - 1, :2]
        ab = plan[i + 1, :2] - plan[i, :2]
        if float(oa @ ab) < 0.0:
            return math.hypot(plan[i, 0], plan[i, 1])
        rotating = (math.hypot(*oa) == 0.0 and plan[i - 1, 2] != plan[i, 2]) or \
            (math.hypot(*ab) == 0.0 and plan[i, 2] != plan[i + 1, 2])
        if rotating:
            return math.hypot(plan[i, 0], plan[i, 1])
    return math.inf


def rotate_to_heading(angle: float, current_wz: float, angular_vel: float,
                      max_angular_accel: float, dt: float) -> float:
    """rotateToHeading: turn in place at rotate_to_heading_angular_vel, within the
    acceleration limit, slowing so as not to overshoot."""
    sign = 1.0 if angle > 0.0 else -1.0
    wz = sign * angular_vel
    wz = min(max(wz, current_wz - max_angular_accel * dt), current_wz + max_angular_accel * dt)
    max_to_stop = math.sqrt(2.0 * max_angular_accel * abs(angle))
    if abs(wz) > max_to_stop:
        wz = sign * max_to_stop
    return wz
