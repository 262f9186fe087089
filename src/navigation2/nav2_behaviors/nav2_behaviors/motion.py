"""The behaviours' maths as plain functions (upstream's Spin, DriveOnHeading, AssistedTeleop
and nav2_costmap_2d's FootprintCollisionChecker), so they can be tested without ROS.

A pose is (x, y, theta); a footprint a list of (x, y) vertices; a costmap a 2-D numpy array
of Nav2 costs indexed [my, mx] with its origin and resolution.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator, Sequence

import numpy as np

LETHAL_OBSTACLE = 254

Pose2D = tuple[float, float, float]
Point = tuple[float, float]


def yaw_of(qx: float, qy: float, qz: float, qw: float) -> float:
    """tf2::getYaw of a quaternion."""
    return math.atan2(2.0 * (qw * qz + qx * qy), 1.0 - 2.0 * (qy * qy + qz * qz))


def yaw_step(previous: float, current: float) -> float:
    """Spin's delta between two yaws: a jump over +-pi counts the short way round."""
    delta = current - previous
    if abs(delta) > math.pi:
        delta = math.copysign(2.0 * math.pi - abs(delta), previous)
    return delta


def spin_speed(remaining_yaw: float, acc_lim: float, min_vel: float, max_vel: float) -> float:
    """Spin's command: the speed that can still stop in time, within [min_vel, max_vel]."""
    speed = math.sqrt(2.0 * acc_lim * max(remaining_yaw, 0.0))
    return min(max(speed, min_vel), max_vel)


def spin_poses_ahead(pose: Pose2D, angular_z: float, relative_yaw: float,
                     cycle_frequency: float, simulate_ahead_time: float) -> Iterator[Pose2D]:
    """The poses Spin checks for collision: its turn simulated cycle by cycle, up to
    simulate_ahead_time, stopping where the simulated turn reaches `relative_yaw` (upstream
    compares with the yaw turned so far)."""
    for cycle in range(int(cycle_frequency * simulate_ahead_time)):
        change = angular_z * (cycle / cycle_frequency)
        if abs(relative_yaw) - abs(change) <= 0.0:
            return
        yield pose[0], pose[1], pose[2] + change


def drive_poses_ahead(pose: Pose2D, linear_x: float, remaining: float,
                      cycle_frequency: float, simulate_ahead_time: float) -> Iterator[Pose2D]:
    """The poses DriveOnHeading/BackUp check: straight along the heading, cycle by cycle, up
    to simulate_ahead_time or the distance still to go."""
    for cycle in range(int(cycle_frequency * simulate_ahead_time)):
        change = linear_x * (cycle / cycle_frequency)
        if remaining - abs(change) <= 0.0:
            return
        yield (pose[0] + change * math.cos(pose[2]), pose[1] + change * math.sin(pose[2]),
               pose[2])


def project_pose(pose: Pose2D, vx: float, vy: float, wz: float, dt: float) -> Pose2D:
    """AssistedTeleop::projectPose (upstream's sign of the lateral term kept)."""
    x, y, theta = pose
    return (x + dt * (vx * math.cos(theta) + vy * math.sin(theta)),
            y + dt * (vx * math.sin(theta) - vy * math.cos(theta)),
            theta + dt * wz)


def teleop_scale(collides: Callable[[Pose2D], bool], pose: Pose2D, vx: float, vy: float,
                 wz: float, step: float, projection_time: float) -> float:
    """AssistedTeleop: 0 when the first step collides, time/projection_time when a later one
    does, 1 when none within projection_time does."""
    time = step
    projected = pose
    while time < projection_time:
        projected = project_pose(projected, vx, vy, wz, step)
        if collides(projected):
            return 0.0 if time == step else time / projection_time
        time += step
    return 1.0


def transform_footprint(pose: Pose2D, footprint: Sequence[Point]) -> list[Point]:
    x, y, theta = pose
    c, s = math.cos(theta), math.sin(theta)
    return [(x + c * px - s * py, y + s * px + c * py) for px, py in footprint]


def footprint_to_robot_frame(footprint: Sequence[Point], robot: Pose2D) -> list[Point]:
    """A footprint published in the costmap's frame, moved into the robot's own frame."""
    x, y, theta = robot
    c, s = math.cos(-theta), math.sin(-theta)
    return [(c * (px - x) - s * (py - y), s * (px - x) + c * (py - y)) for px, py in footprint]


def world_to_map(wx: float, wy: float, origin: Point, resolution: float,
                 size: tuple[int, int]) -> tuple[int, int] | None:
    """Costmap2D::worldToMap: truncating, None outside (size is (size_x, size_y))."""
    if wx < origin[0] or wy < origin[1]:
        return None
    mx = int((wx - origin[0]) / resolution)
    my = int((wy - origin[1]) / resolution)
    if mx < size[0] and my < size[1]:
        return mx, my
    return None


def line_cells(x0: int, y0: int, x1: int, y1: int) -> Iterator[tuple[int, int]]:
    """nav2_util::LineIterator: Bresenham's cells from (x0, y0) to (x1, y1), both included."""
    dx, dy = abs(x1 - x0), abs(y1 - y0)
    sx, sy = (1 if x1 >= x0 else -1), (1 if y1 >= y0 else -1)
    if dx >= dy:
        error = dx // 2
        y = y0
        for x in range(x0, x1 + sx, sx):
            yield x, y
            error -= dy
            if error < 0:
                y += sy
                error += dx
    else:
        error = dy // 2
        x = x0
        for y in range(y0, y1 + sy, sy):
            yield x, y
            error -= dx
            if error < 0:
                x += sx
                error += dy


def footprint_cost(costs: np.ndarray, origin: Point, resolution: float,
                   footprint: Sequence[Point]) -> float:
    """FootprintCollisionChecker::footprintCost: the highest cost under the footprint's
    outline; a vertex off the map is LETHAL_OBSTACLE."""
    size = (costs.shape[1], costs.shape[0])
    cells = [world_to_map(x, y, origin, resolution, size) for x, y in footprint]
    if not cells or any(cell is None for cell in cells):
        return float(LETHAL_OBSTACLE)
    worst = 0.0
    for start, end in zip(cells, cells[1:] + cells[:1], strict=False):
        for mx, my in line_cells(start[0], start[1], end[0], end[1]):
            cost = float(costs[my, mx])
            if cost == LETHAL_OBSTACLE:
                return cost
            worst = max(worst, cost)
    return worst
