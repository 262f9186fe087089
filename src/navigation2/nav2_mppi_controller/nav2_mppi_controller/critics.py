"""mppi::critics in numpy: each adds its cost of every rolled-out trajectory to `data.costs`.

Upstream's per-trajectory loops (CostCritic, PathAlignCritic) are vectorised over the batch;
their formulas, parameters, defaults and thresholds are upstream's.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np
from nav2_costmap_2d.cost_values import (
    INSCRIBED_INFLATED_OBSTACLE,
    LETHAL_OBSTACLE,
    NO_INFORMATION,
)

ParamGetter = Callable[[str, Any], Any]


def normalize(angles: np.ndarray) -> np.ndarray:
    return (angles + np.float32(math.pi)) % np.float32(2 * math.pi) - np.float32(math.pi)


@dataclass
class Grid:
    """A snapshot of the local costmap: costs[my, mx], origin and resolution."""

    costs: np.ndarray
    origin_x: float
    origin_y: float
    resolution: float
    tracking_unknown: bool

    def lookup(self, x: np.ndarray, y: np.ndarray) -> np.ndarray:
        """The cost under each point; NO_INFORMATION outside the grid (worldToMap fails)."""
        fx = (x - self.origin_x) / self.resolution
        fy = (y - self.origin_y) / self.resolution
        h, w = self.costs.shape
        inside = (fx >= 0) & (fy >= 0) & (fx < w) & (fy < h)
        mx = np.where(inside, fx, 0).astype(np.int64)
        my = np.where(inside, fy, 0).astype(np.int64)
        return np.where(inside, self.costs[my, mx], NO_INFORMATION).astype(np.float32)


@dataclass
class CriticData:
    pose: tuple[float, float, float]
    vx: np.ndarray  # (batch, steps) velocities of the rollouts
    wz: np.ndarray
    x: np.ndarray  # (batch, steps) trajectories
    y: np.ndarray
    yaws: np.ndarray
    path: np.ndarray  # (P, 3) the pruned plan in the costmap frame
    goal: tuple[float, float, float]
    model_dt: float
    grid: Grid
    costs: np.ndarray
    fail_flag: bool = False
    furthest: int | None = None
    path_valid: np.ndarray | None = field(default=None)

    def goal_within(self, threshold: float) -> bool:
        """utils::withinPositionGoalTolerance."""
        return (self.goal[0] - self.pose[0]) ** 2 + (self.goal[1] - self.pose[1]) ** 2 < \
            threshold ** 2

    def furthest_reached(self) -> int:
        """The furthest path point a trajectory's end is nearest to (upstream carries a running
        lower bound across trajectories; the maximum of their nearest points is the same in
        all but pathological batches)."""
        if self.furthest is None:
            dx = self.path[None, :, 0] - self.x[:, -1:]
            dy = self.path[None, :, 1] - self.y[:, -1:]
            self.furthest = int(np.argmin(dx * dx + dy * dy, axis=1).max())
        return self.furthest

    def path_points_valid(self) -> np.ndarray:
        """utils::findPathCosts: path points not in lethal/inscribed cost (unknown: only when
        tracking unknown space), for all but the last point."""
        if self.path_valid is None:
            costs = self.grid.lookup(self.path[:-1, 0], self.path[:-1, 1])
            fx = (self.path[:-1, 0] - self.grid.origin_x) / self.grid.resolution
            fy = (self.path[:-1, 1] - self.grid.origin_y) / self.grid.resolution
            h, w = self.grid.costs.shape
            inside = (fx >= 0) & (fy >= 0) & (fx < w) & (fy < h)
            valid = (costs != LETHAL_OBSTACLE) & (costs != INSCRIBED_INFLATED_OBSTACLE)
            valid &= (costs != NO_INFORMATION) | self.grid.tracking_unknown
            self.path_valid = valid & inside
        return self.path_valid


class Critic:
    defaults: ClassVar[dict[str, Any]] = {}
    weight_default = 1.0

    def __init__(self, name: str, param: ParamGetter, parent: ParamGetter) -> None:
        self.name = name
        self.enabled = bool(param('enabled', True))
        self.power = int(param('cost_power', 1))
        self.weight = float(param('cost_weight', self.weight_default))
        for key, default in self.defaults.items():
            setattr(self, key, param(key, default))

    def add(self, data: CriticData, cost: np.ndarray) -> None:
        data.costs += cost ** self.power if self.power > 1 else cost

    def score(self, data: CriticData) -> None:
        raise NotImplementedError


class ConstraintCritic(Critic):
    weight_default = 4.0

    def __init__(self, name: str, param: ParamGetter, parent: ParamGetter) -> None:
        super().__init__(name, param, parent)
        vx_max, vy_max = float(parent('vx_max', 0.5)), float(parent('vy_max', 0.0))
        vx_min = float(parent('vx_min', -0.35))
        self.max_vel = math.hypot(vx_max, vy_max)
        self.min_vel = (1.0 if vx_min > 0 else -1.0) * math.hypot(vx_min, vy_max)

    def score(self, data: CriticData) -> None:
        if self.enabled:
            out = np.maximum(data.vx - self.max_vel, 0) + np.maximum(self.min_vel - data.vx, 0)
            self.add(data, (out * data.model_dt).sum(axis=1) * self.weight)


class GoalCritic(Critic):
    weight_default = 5.0
    defaults: ClassVar[dict[str, Any]] = {'threshold_to_consider': 1.4}

    def score(self, data: CriticData) -> None:
        if self.enabled and data.goal_within(self.threshold_to_consider):
            dist = np.hypot(data.x - data.goal[0], data.y - data.goal[1])
            self.add(data, dist.mean(axis=1) * self.weight)


class GoalAngleCritic(Critic):
    weight_default = 3.0
    defaults: ClassVar[dict[str, Any]] = {'threshold_to_consider': 0.5,
                                          'symmetric_yaw_tolerance': False}

    def score(self, data: CriticData) -> None:
        if not (self.enabled and data.goal_within(self.threshold_to_consider)):
            return
        goal_yaw = data.path[-1, 2]
        dist = np.abs(normalize(goal_yaw - data.yaws))
        if self.symmetric_yaw_tolerance:
            dist = np.minimum(dist, np.abs(normalize(goal_yaw + math.pi - data.yaws)))
        self.add(data, dist.mean(axis=1) * self.weight)


class PreferForwardCritic(Critic):
    weight_default = 5.0
    defaults: ClassVar[dict[str, Any]] = {'threshold_to_consider': 0.5}

    def score(self, data: CriticData) -> None:
        if self.enabled and not data.goal_within(self.threshold_to_consider):
            backwards = np.maximum(-data.vx, 0) * data.model_dt
            self.add(data, backwards.sum(axis=1) * self.weight)


class TwirlingCritic(Critic):
    weight_default = 10.0

    def score(self, data: CriticData) -> None:
        if self.enabled and not data.goal_within(0.25):
            self.add(data, np.abs(data.wz).mean(axis=1) * self.weight)


class PathFollowCritic(Critic):
    weight_default = 5.0
    defaults: ClassVar[dict[str, Any]] = {'threshold_to_consider': 1.4, 'offset_from_furthest': 6}

    def score(self, data: CriticData) -> None:
        if not self.enabled or len(data.path) < 2 or \
                data.goal_within(self.threshold_to_consider):
            return
        last = len(data.path) - 1
        index = min(data.furthest_reached() + int(self.offset_from_furthest), last)
        valid = data.path_points_valid()
        while index < last - 1 and not valid[index]:
            index += 1
        px, py = data.path[index, 0], data.path[index, 1]
        self.add(data, self.weight * np.hypot(data.x[:, -1] - px, data.y[:, -1] - py))


class PathAngleCritic(Critic):
    weight_default = 2.2
    defaults: ClassVar[dict[str, Any]] = {'offset_from_furthest': 4, 'threshold_to_consider': 0.5,
                'max_angle_to_furthest': 0.785398, 'mode': 0}
    MODES = ('Forward Preference', 'No Directional Preference',
             'Consider Feasible Path Orientations')

    def __init__(self, name: str, param: ParamGetter, parent: ParamGetter) -> None:
        super().__init__(name, param, parent)
        self.mode = int(self.mode)
        if self.mode not in (0, 1, 2):
            raise ValueError(f'{name}.mode: must be 0, 1 or 2, got {self.mode}')
        self.reversing_allowed = float(parent('vx_min', -0.35)) < -1e-6
        self.warning = ''
        if not self.reversing_allowed and self.mode == 1:
            self.mode = 0
            self.warning = ('Path angle mode set to no directional preference, but controller\'s '
                            'settings don\'t allow for reversing! Setting mode to forward '
                            'preference.')

    def score(self, data: CriticData) -> None:
        if not self.enabled or data.goal_within(self.threshold_to_consider):
            return
        index = min(data.furthest_reached() + int(self.offset_from_furthest),
                    len(data.path) - 1)
        gx, gy, gyaw = data.path[index]
        x, y, yaw = data.pose
        to_point = math.atan2(gy - y, gx - x)
        if self.mode == 0:
            angle = abs(normalize(np.float32(yaw - to_point)))
        elif self.mode == 1:
            angle = min(abs(normalize(np.float32(yaw - to_point))),
                        abs(normalize(np.float32(yaw + math.pi - to_point))))
        else:
            if abs(normalize(np.float32(gyaw - to_point))) > math.pi / 2:
                to_point += math.pi
            angle = abs(normalize(np.float32(yaw - to_point)))
        if angle < self.max_angle_to_furthest:
            return
        between = np.arctan2(gy - data.y[:, -1], gx - data.x[:, -1])
        end_yaws = data.yaws[:, -1]
        if self.mode == 1:
            flip = np.abs(normalize(between - end_yaws)) >= math.pi / 2
            between = np.where(flip, normalize(between + math.pi), between)
        elif self.mode == 2:
            flip = np.abs(normalize(gyaw - between)) >= math.pi / 2
            between = np.where(flip, normalize(between + math.pi), between)
        self.add(data, np.abs(normalize(between - end_yaws)) * self.weight)


class PathAlignCritic(Critic):
    weight_default = 10.0
    defaults: ClassVar[dict[str, Any]] = {
                'max_path_occupancy_ratio': 0.07, 'offset_from_furthest': 20,
                'trajectory_point_step': 4, 'threshold_to_consider': 0.5,
                'use_path_orientations': False}

    def score(self, data: CriticData) -> None:
        if not self.enabled or data.goal_within(self.threshold_to_consider):
            return
        segments = data.furthest_reached()
        if segments < int(self.offset_from_furthest):
            return
        valid = data.path_points_valid()[:segments]
        invalid = np.cumsum(~valid)
        ratio_hit = (invalid / float(segments) > self.max_path_occupancy_ratio) & (invalid > 2)
        if ratio_hit.any():
            return
        path = data.path[:segments]
        integrated = np.concatenate([[0.0], np.cumsum(np.hypot(
            np.diff(path[:, 0]), np.diff(path[:, 1])))]).astype(np.float32)
        step = max(int(self.trajectory_point_step), 1)
        tx, ty, tyaw = data.x[:, ::step], data.y[:, ::step], data.yaws[:, ::step]
        travelled = np.cumsum(np.hypot(np.diff(tx, axis=1), np.diff(ty, axis=1)), axis=1)
        # findClosestPathPt: the path point whose integrated distance is nearest
        above = np.searchsorted(integrated, travelled, side='right')
        above = np.minimum(above, segments - 1)
        below = np.maximum(above - 1, 0)
        nearer_below = (travelled - integrated[below]) < (integrated[above] - travelled)
        point = np.where((above > 0) & nearer_below & (travelled < integrated[-1]), below,
                         above)
        point = np.where(travelled >= integrated[-1], segments - 1, point)
        dx = path[point, 0] - tx[:, 1:]
        dy = path[point, 1] - ty[:, 1:]
        dist2 = dx * dx + dy * dy
        if self.use_path_orientations:
            dist2 = dist2 + normalize(tyaw[:, 1:] - path[point, 2]) ** 2
        use = valid[point]
        samples = use.sum(axis=1)
        summed = np.where(use, np.sqrt(dist2), 0.0).sum(axis=1)
        cost = np.where(samples > 0, summed / np.maximum(samples, 1), 0.0)
        self.add(data, cost.astype(np.float32) * self.weight)


class CostCritic(Critic):
    weight_default = 3.81
    defaults: ClassVar[dict[str, Any]] = {
                'consider_footprint': False, 'critical_cost': 300.0, 'near_collision_cost': 253,
                'collision_cost': 1000000.0, 'near_goal_distance': 0.5,
                'inflation_layer_name': '', 'trajectory_point_step': 2}

    def __init__(self, name: str, param: ParamGetter, parent: ParamGetter) -> None:
        super().__init__(name, param, parent)
        self.weight /= 254.0  # upstream scales the weight to the cost range

    def score(self, data: CriticData) -> None:
        """Circular collision checking (consider_footprint is read, the footprint is not
        swept: a cell at or above INSCRIBED_INFLATED_OBSTACLE under the centre collides)."""
        if not self.enabled:
            return
        step = max(int(self.trajectory_point_step), 1)
        length = data.x.shape[1] // step
        x, y = data.x[:, ::step][:, :length], data.y[:, ::step][:, :length]
        cost = data.grid.lookup(x, y)
        unknown = cost == NO_INFORMATION
        collide = (cost >= INSCRIBED_INFLATED_OBSTACLE) & ~unknown
        if not data.grid.tracking_unknown:
            collide |= unknown
        near_goal = data.goal_within(self.near_goal_distance)
        point_cost = np.where(cost >= self.near_collision_cost, self.critical_cost,
                              0.0 if near_goal else cost)
        collided = collide.any(axis=1)
        repulsive = np.where(collided, self.collision_cost, point_cost.sum(axis=1))
        self.add(data, (repulsive * (self.weight / length)).astype(np.float32))
        data.fail_flag = bool(collided.all())


CRITICS = {cls.__name__: cls for cls in (
    ConstraintCritic, CostCritic, GoalCritic, GoalAngleCritic, PathAlignCritic,
    PathFollowCritic, PathAngleCritic, PreferForwardCritic, TwirlingCritic)}
