"""nav2_navfn_planner's pure maths: NavFn's costs, paths around obstacles, nav2_core's errors."""

from __future__ import annotations

import math

import numpy as np
import pytest
from nav2_costmap_2d.cost_values import LETHAL_OBSTACLE, NO_INFORMATION
from nav2_costmap_2d.costmap_2d import Costmap2D
from nav2_navfn_planner.exceptions import (
    GoalOccupied,
    GoalOutsideMapBounds,
    NoValidPathCouldBeFound,
    NoViapointsGiven,
    StartOutsideMapBounds,
)
from nav2_navfn_planner.navfn import COST_OBS, navfn_costs
from nav2_navfn_planner.navfn_planner import NavfnPlanner, path_length


def _costmap(cells: int = 100, value: int = 0) -> Costmap2D:
    grid = Costmap2D(cells, cells, 0.05, 0.0, 0.0)
    grid.costmap[:] = value
    return grid


def _costs_along(costmap: Costmap2D, plan: list[tuple[float, float, float]]) -> np.ndarray:
    cells = [costmap.world_to_map(x, y) for x, y, _ in plan]
    assert all(cell is not None for cell in cells)
    return np.array([costmap.costmap[my, mx] for mx, my in cells])


def test_navfn_translates_costs_as_setcostmap():
    ros = np.array([[0, 100, 252, 253, 254, 255]] * 3, dtype=np.uint8)
    ros = np.pad(ros, 1)  # NavFn makes the border an obstacle: keep the values off it
    costs = navfn_costs(ros, allow_unknown=True)[2, 1:-1]
    assert costs.tolist() == [50, 130, 251, COST_OBS, COST_OBS, 253]
    assert navfn_costs(ros, allow_unknown=False)[2, -2] == COST_OBS
    assert (navfn_costs(ros)[0] == COST_OBS).all()


def test_open_space_path_is_straight_and_ends_on_the_goal():
    costmap = _costmap()
    plan = NavfnPlanner().create_plan(costmap, (0.5, 0.5, 0.0), (4.0, 2.5, 1.0))
    straight = math.hypot(3.5, 2.0)
    assert path_length(plan) == pytest.approx(straight, rel=0.02)
    assert plan[0][:2] == pytest.approx((0.5, 0.5), abs=0.06)
    assert plan[-1] == (4.0, 2.5, 1.0)  # the goal pose itself, with its orientation
    # NavFn's spacing: half a cell between poses (the first is the robot's cell itself)
    steps = np.hypot(*np.diff(np.array([p[:2] for p in plan[1:-1]]), axis=0).T)
    assert steps.max() <= 0.05 * 0.5 + 1e-6
    # every point stays within a cell and a half of the straight line
    for x, y, _ in plan:
        assert abs((y - 0.5) * 3.5 - (x - 0.5) * 2.0) / straight < 0.075


def test_path_goes_around_a_wall_near_the_shortest_way():
    costmap = _costmap()
    # a wall at x = 2.5 m from y = 0.5 to 4.5 m, inscribed cells 0.15 m around it
    costmap.costmap[7:93, 47:54] = 253
    costmap.costmap[10:90, 50] = LETHAL_OBSTACLE
    plan = NavfnPlanner().create_plan(costmap, (1.0, 2.5, 0.0), (4.0, 2.5, 0.0))
    assert (_costs_along(costmap, plan) < LETHAL_OBSTACLE).all()
    assert max(y for _, y, _ in plan) > 4.6  # round the wall's end, not through it
    # the shortest way passes the wall's end at (2.5, 4.5): two straight legs
    shortest = 2 * math.hypot(1.5, 2.0)
    assert shortest <= path_length(plan) <= shortest * 1.1


def test_path_prefers_low_cost_when_the_detour_is_cheap():
    costmap = _costmap()
    costmap.costmap[30:70, 40:60] = 200  # an expensive (not lethal) patch on the straight line
    plan = NavfnPlanner().create_plan(costmap, (0.5, 2.5, 0.0), (4.5, 2.5, 0.0))
    costs = _costs_along(costmap, plan)
    assert (costs < 200).all()  # it goes round the patch
    assert path_length(plan) < 6.0


def test_unknown_space_is_crossed_only_when_allowed():
    costmap = _costmap()
    costmap.costmap[:, 45:55] = NO_INFORMATION  # a band of unknown across the map
    start, goal = (1.0, 2.5, 0.0), (4.0, 2.5, 0.0)
    plan = NavfnPlanner('GridBased', {'allow_unknown': True}).create_plan(costmap, start, goal)
    assert (_costs_along(costmap, plan) == NO_INFORMATION).any()
    with pytest.raises(NoValidPathCouldBeFound,
                       match=r'^Failed to create plan with tolerance of: 0\.500000$') as error:
        NavfnPlanner('GridBased', {'allow_unknown': False}).create_plan(costmap, start, goal)
    assert error.value.error_code() == 208 and error.value.error_code(through_poses=True) == 308


def test_enclosed_goal_has_no_valid_path():
    costmap = _costmap()
    # a closed room wider than the goal tolerance (0.5 m) around the goal
    costmap.costmap[50:90, 50] = costmap.costmap[50:90, 89] = LETHAL_OBSTACLE
    costmap.costmap[50, 50:90] = costmap.costmap[89, 50:90] = LETHAL_OBSTACLE
    with pytest.raises(NoValidPathCouldBeFound) as error:
        NavfnPlanner().create_plan(costmap, (1.0, 1.0, 0.0), (3.5, 3.5, 0.0))
    assert error.value.code_name == 'NO_VALID_PATH'


def test_goal_within_tolerance_of_a_reachable_cell():
    costmap = _costmap()
    costmap.costmap[68:73, 68:73] = LETHAL_OBSTACLE  # the goal sits in a small obstacle
    plan = NavfnPlanner('GridBased', {'tolerance': 0.5}).create_plan(
        costmap, (1.0, 1.0, 0.0), (3.5, 3.5, 0.0))
    end = plan[-1]
    assert math.hypot(end[0] - 3.5, end[1] - 3.5) <= 0.5
    assert costmap.costmap[costmap.world_to_map(end[0], end[1])[::-1]] < LETHAL_OBSTACLE
    with pytest.raises(GoalOccupied, match=r'^Goal Coordinates of\(3\.500000, 3\.500000\) '
                       r'was in lethal cost$') as error:
        NavfnPlanner('GridBased', {'tolerance': 0.0}).create_plan(
            costmap, (1.0, 1.0, 0.0), (3.5, 3.5, 0.0))
    assert error.value.error_code() == 206


def test_outside_the_map_is_refused():
    costmap = _costmap()
    planner = NavfnPlanner()
    with pytest.raises(StartOutsideMapBounds, match=r'^Start Coordinates of\(-1\.000000, '
                       r'1\.000000\) was outside bounds$') as error:
        planner.create_plan(costmap, (-1.0, 1.0, 0.0), (2.0, 2.0, 0.0))
    assert error.value.error_code() == 203
    with pytest.raises(GoalOutsideMapBounds, match=r'^Goal Coordinates of') as error:
        planner.create_plan(costmap, (1.0, 1.0, 0.0), (2.0, 5.0, 0.0))
    assert error.value.error_code() == 204


def test_start_equal_to_goal_gives_one_pose():
    costmap = _costmap()
    plan = NavfnPlanner().create_plan(costmap, (1.0, 1.0, 0.0), (1.0, 1.0, 2.0))
    assert plan == [(1.0, 1.0, 2.0)]
    planner = NavfnPlanner('GridBased', {'use_final_approach_orientation': True})
    assert planner.create_plan(costmap, (1.0, 1.0, 0.0), (1.0, 1.0, 2.0)) == [(1.0, 1.0, 0.0)]


def test_final_approach_orientation_faces_along_the_path():
    costmap = _costmap()
    planner = NavfnPlanner('GridBased', {'use_final_approach_orientation': True})
    plan = planner.create_plan(costmap, (1.0, 1.0, 0.0), (3.0, 3.0, -2.0))
    assert plan[-1][2] == pytest.approx(math.pi / 4, abs=0.1)


def test_start_in_an_obstacle_is_cleared_like_the_robot_cell():
    costmap = _costmap()
    costmap.costmap[20, 20] = LETHAL_OBSTACLE
    plan = NavfnPlanner().create_plan(costmap, (1.0, 1.0, 0.0), (3.0, 1.0, 0.0))
    assert path_length(plan) == pytest.approx(2.0, rel=0.03)
    assert costmap.costmap[20, 20] == LETHAL_OBSTACLE  # the caller's costmap is left as is


def test_through_poses_plans_each_leg():
    costmap = _costmap()
    planner = NavfnPlanner()
    plan = planner.create_plan_through_poses(costmap, (0.5, 0.5, 0.0),
                                             [(2.5, 0.5, 0.0), (2.5, 3.0, 1.5)])
    assert path_length(plan) == pytest.approx(4.5, rel=0.03)
    assert plan[-1] == (2.5, 3.0, 1.5)
    with pytest.raises(NoViapointsGiven) as error:
        planner.create_plan_through_poses(costmap, (0.5, 0.5, 0.0), [])
    assert error.value.error_code(through_poses=True) == 309


def test_parameters_are_checked_in_one_line():
    with pytest.raises(ValueError, match=r'^GridBased\.tolerance: expected float, got .x.$'):
        NavfnPlanner('GridBased', {'tolerance': 'x'})
    with pytest.raises(ValueError, match=r'^GridBased\.allow_unknown: expected bool, got 1$'):
        NavfnPlanner('GridBased', {'allow_unknown': 1})
    assert NavfnPlanner('GridBased', {'tolerance': 1}).tolerance == 1.0


def test_plans_become_nav_msgs_paths():
    from geometry_msgs.msg import PoseStamped
    from nav2_navfn_planner.messages import path_msg, pose_from_msg
    goal = PoseStamped()
    goal.pose.position.x, goal.pose.position.y = 3.0, 1.0
    goal.pose.orientation.z, goal.pose.orientation.w = math.sin(0.5), math.cos(0.5)
    assert pose_from_msg(goal) == pytest.approx((3.0, 1.0, 1.0))
    plan = NavfnPlanner().create_plan(_costmap(), (1.0, 1.0, 0.0), pose_from_msg(goal))
    path = path_msg(plan, 'map')
    assert path.header.frame_id == 'map' and len(path.poses) == len(plan)
    assert path.poses[0].pose.orientation.w == 1.0  # NavFn's poses carry no heading...
    assert pose_from_msg(path.poses[-1]) == pytest.approx((3.0, 1.0, 1.0))  # ...but the goal's


def test_a_cancelled_plan_raises_planner_cancelled():
    from nav2_navfn_planner.exceptions import PlannerCancelled
    with pytest.raises(PlannerCancelled, match=r'^Planner was cancelled$'):
        NavfnPlanner().create_plan(_costmap(), (1.0, 1.0, 0.0), (3.0, 3.0, 0.0),
                                   cancel_checker=lambda: True)
