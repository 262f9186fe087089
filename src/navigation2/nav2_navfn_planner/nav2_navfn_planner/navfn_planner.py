"""NavfnPlanner: the GridBased plugin of planner_server (nav2_navfn_planner::NavfnPlanner).

Parameters under the plugin's name, with upstream's defaults: `tolerance` (0.5 m),
`use_astar` (False), `allow_unknown` (True), `use_final_approach_orientation` (False).
Poses are (x, y, yaw) in the costmap's frame; a plan is a list of them from start to goal.
Failures raise nav2_core's exceptions (nav2_navfn_planner.exceptions) with upstream's texts.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from typing import Any, Protocol

import numpy as np

from nav2_navfn_planner.exceptions import (
    GoalOccupied,
    GoalOutsideMapBounds,
    NoValidPathCouldBeFound,
    NoViapointsGiven,
    StartOutsideMapBounds,
)
from nav2_navfn_planner.navfn import POT_HIGH, GradientPath, navfn_costs, potential_field

Pose = tuple[float, float, float]
LETHAL_OBSTACLE = 254
FREE_SPACE = 0
PARAMETERS: dict[str, Any] = {'tolerance': 0.5, 'use_astar': False, 'allow_unknown': True,
                              'use_final_approach_orientation': False}


class CostmapLike(Protocol):
    """What the planner reads of a nav2_costmap_2d Costmap2D."""

    costmap: np.ndarray
    resolution: float
    origin_x: float
    origin_y: float
    size_x: int
    size_y: int

    def world_to_map(self, wx: float, wy: float) -> tuple[int, int] | None: ...


class NavfnPlanner:
    """Plans on a costmap: NavFn's potential from the start, descended from the goal."""

    def __init__(self, name: str = 'GridBased', params: Mapping[str, Any] | None = None) -> None:
        self.name = name
        self.tolerance = 0.5
        self.use_astar = False
        self.allow_unknown = True
        self.use_final_approach_orientation = False
        self.set_parameters(params or {})
        self.last_potential: np.ndarray | None = None

    def set_parameters(self, params: Mapping[str, Any]) -> None:
        """Take parameters (plugin-relative names); a wrong type raises one line naming it."""
        for key, value in params.items():
            if key not in PARAMETERS:
                continue
            default = PARAMETERS[key]
            if isinstance(default, float) and isinstance(value, int) and not isinstance(
                    value, bool):
                value = float(value)
            if type(value) is not type(default):
                raise ValueError(f'{self.name}.{key}: expected {type(default).__name__}, '
                                 f'got {value!r}')
            if key == 'tolerance' and value < 0:
                raise ValueError(f'{self.name}.tolerance: must be >= 0, got {value}')
            setattr(self, key, value)

    # --- upstream's own world <-> map: rounded, cells centred on origin + i * resolution --
    @staticmethod
    def _world_to_map(costmap: CostmapLike, wx: float, wy: float) -> tuple[int, int] | None:
        if wx < costmap.origin_x or wy < costmap.origin_y:
            return None
        mx = round((wx - costmap.origin_x) / costmap.resolution)
        my = round((wy - costmap.origin_y) / costmap.resolution)
        if mx < costmap.size_x and my < costmap.size_y:
            return mx, my
        return None

    # --- planning ------------------------------------------------------------------------
    def create_plan(self, costmap: CostmapLike, start: Pose, goal: Pose,
                    cancel_checker: Callable[[], bool] | None = None) -> list[Pose]:
        if costmap.world_to_map(start[0], start[1]) is None:
            raise StartOutsideMapBounds(
                f'Start Coordinates of({start[0]:.6f}, {start[1]:.6f}) was outside bounds')
        goal_cell = costmap.world_to_map(goal[0], goal[1])
        if goal_cell is None:
            raise GoalOutsideMapBounds(
                f'Goal Coordinates of({goal[0]:.6f}, {goal[1]:.6f}) was outside bounds')
        if (self.tolerance == 0
                and costmap.costmap[goal_cell[1], goal_cell[0]] == LETHAL_OBSTACLE):
            raise GoalOccupied(
                f'Goal Coordinates of({goal[0]:.6f}, {goal[1]:.6f}) was in lethal cost')
        if start[0] == goal[0] and start[1] == goal[1]:
            yaw = start[2]
            if start[2] != goal[2] and not self.use_final_approach_orientation:
                yaw = goal[2]
            return [(start[0], start[1], yaw)]
        plan = self.make_plan(costmap, start, goal, self.tolerance, cancel_checker)
        if not plan:
            raise NoValidPathCouldBeFound(
                f'Failed to create plan with tolerance of: {self.tolerance:.6f}')
        return plan

    def make_plan(self, costmap: CostmapLike, start: Pose, goal: Pose, tolerance: float,
                  cancel_checker: Callable[[], bool] | None = None) -> list[Pose]:
        size_x, size_y = costmap.size_x, costmap.size_y
        start_cell = self._clamped_cell(costmap, start)
        ros = costmap.costmap.copy()
        ros[start_cell[1], start_cell[0]] = FREE_SPACE  # the robot's own cell is never an obstacle
        costs = navfn_costs(ros, self.allow_unknown)
        # use_astar is accepted: the fast-marching field is cheap enough to grow everywhere,
        # and A* would only stop it earlier with the same path
        potential = potential_field(costs, start_cell)
        self.last_potential = potential
        best = self._reachable_goal(costmap, potential, goal, tolerance)
        if best is None:
            return []
        goal_cell = self._world_to_map(costmap, best[0], best[1])
        assert goal_cell is not None
        points = GradientPath(potential, start_cell).calc_path(
            goal_cell, 4 * max(size_x, size_y), cancel_checker)
        if not points:
            return []
        plan: list[Pose] = [(costmap.origin_x + x * costmap.resolution,
                             costmap.origin_y + y * costmap.resolution, 0.0)
                            for x, y in reversed(points)]
        self._smooth_approach_to_goal(best, plan)
        if self.use_final_approach_orientation:
            self._final_approach_orientation(start, plan)
        return plan

    def _clamped_cell(self, costmap: CostmapLike, pose: Pose) -> tuple[int, int]:
        """Upstream's rounding may land one past the last cell: keep it on the map."""
        mx = round((pose[0] - costmap.origin_x) / costmap.resolution)
        my = round((pose[1] - costmap.origin_y) / costmap.resolution)
        return min(max(mx, 0), costmap.size_x - 1), min(max(my, 0), costmap.size_y - 1)

    def _point_potential(self, costmap: CostmapLike, potential: np.ndarray, wx: float,
                         wy: float) -> float:
        cell = self._world_to_map(costmap, wx, wy)
        if cell is None:
            return math.inf
        return float(potential[cell[1], cell[0]])

    def _reachable_goal(self, costmap: CostmapLike, potential: np.ndarray, goal: Pose,
                        tolerance: float) -> Pose | None:
        """The goal if reached, else the reached point nearest to it within the tolerance."""
        if self._point_potential(costmap, potential, goal[0], goal[1]) < POT_HIGH:
            return goal
        best: Pose | None = None
        best_sdist = math.inf
        steps = math.floor(2 * tolerance / costmap.resolution + 1e-9) + 1
        for j in range(steps):
            wy = goal[1] - tolerance + j * costmap.resolution
            for i in range(steps):
                wx = goal[0] - tolerance + i * costmap.resolution
                sdist = (wx - goal[0]) ** 2 + (wy - goal[1]) ** 2
                if sdist < best_sdist and self._point_potential(costmap, potential, wx,
                                                                wy) < POT_HIGH:
                    best_sdist, best = sdist, (wx, wy, goal[2])
        return best

    @staticmethod
    def _smooth_approach_to_goal(goal: Pose, plan: list[Pose]) -> None:
        """End on the goal pose itself: replace the last point or append the goal."""
        if len(plan) >= 2:
            before, last = plan[-2], plan[-1]
            if _sq(last, before) > _sq(goal, before) or _sq(last, goal) < 1e-6:
                plan[-1] = goal
                return
        plan.append(goal)

    @staticmethod
    def _final_approach_orientation(start: Pose, plan: list[Pose]) -> None:
        """The last pose faces the way the path arrives (upstream's corner cases kept)."""
        if len(plan) == 1:
            plan[-1] = (plan[-1][0], plan[-1][1], start[2])
            return
        last, approach = plan[-1], plan[-2]
        if abs(last[0] - approach[0]) < 0.0001 and abs(last[1] - approach[1]) < 0.0001 \
                and len(plan) > 2:
            approach = plan[-3]
        plan[-1] = (last[0], last[1], math.atan2(last[1] - approach[1], last[0] - approach[0]))

    def create_plan_through_poses(self, costmap: CostmapLike, start: Pose,
                                  goals: Sequence[Pose],
                                  cancel_checker: Callable[[], bool] | None = None
                                  ) -> list[Pose]:
        """planner_server's computePlanThroughPoses: one plan per leg, concatenated."""
        if not goals:
            raise NoViapointsGiven('No viapoints given')
        path: list[Pose] = []
        leg_start = start
        for goal in goals:
            leg = self.create_plan(costmap, leg_start, goal, cancel_checker)
            if not leg:
                raise NoValidPathCouldBeFound(f'{self.name} generated a empty path')
            path.extend(leg)
            leg_start = goal
        return path


def _sq(a: Pose, b: Pose) -> float:
    return (a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2


def path_length(plan: Sequence[Pose]) -> float:
    """Length of a plan's polyline in metres."""
    xy = np.asarray([(p[0], p[1]) for p in plan], dtype=np.float64)
    return float(np.hypot(*np.diff(xy, axis=0).T).sum()) if len(xy) > 1 else 0.0
