"""nav2_behaviors.motion: the behaviours' maths as plain functions."""

from __future__ import annotations

import math

import numpy as np
from nav2_behaviors.motion import (
    LETHAL_OBSTACLE,
    drive_poses_ahead,
    footprint_cost,
    footprint_to_robot_frame,
    line_cells,
    spin_poses_ahead,
    spin_speed,
    teleop_scale,
    transform_footprint,
    world_to_map,
    yaw_step,
)

SQUARE = [(0.1, 0.1), (0.1, -0.1), (-0.1, -0.1), (-0.1, 0.1)]


def test_yaw_step_counts_a_jump_over_pi_the_short_way():
    assert yaw_step(0.1, 0.3) == 0.3 - 0.1
    assert math.isclose(yaw_step(3.1, -3.1), 2 * math.pi - 6.2)  # +0.083 rad, not -6.2
    assert math.isclose(yaw_step(-3.1, 3.1), -(2 * math.pi - 6.2))


def test_spin_speed_brakes_towards_the_goal_within_the_limits():
    assert spin_speed(3.0, 3.2, 0.4, 1.0) == 1.0  # far: the maximum
    assert math.isclose(spin_speed(0.1, 3.2, 0.4, 1.0), math.sqrt(0.64))
    assert spin_speed(0.001, 3.2, 0.4, 1.0) == 0.4  # close: never below the minimum


def test_spin_checks_ahead_only_as_far_as_it_has_turned():
    # upstream compares the simulated turn with the yaw turned so far
    assert list(spin_poses_ahead((1, 2, 0.0), 1.0, 0.0, 10.0, 2.0)) == []
    poses = list(spin_poses_ahead((1, 2, 0.0), 1.0, 0.35, 10.0, 2.0))
    assert [round(p[2], 3) for p in poses] == [0.0, 0.1, 0.2, 0.3]
    assert all(p[:2] == (1, 2) for p in poses)
    assert len(list(spin_poses_ahead((0, 0, 0), 1.0, 100.0, 10.0, 2.0))) == 20


def test_drive_checks_ahead_along_the_heading_up_to_the_distance_left():
    poses = list(drive_poses_ahead((0.0, 0.0, math.pi / 2), 0.2, 10.0, 10.0, 2.0))
    assert len(poses) == 20  # simulate_ahead_time * cycle_frequency
    assert math.isclose(poses[-1][1], 0.2 * 1.9) and abs(poses[-1][0]) < 1e-9
    short = list(drive_poses_ahead((0.0, 0.0, 0.0), -0.1, 0.05, 10.0, 2.0))
    assert [round(p[0], 3) for p in short] == [0.0, -0.01, -0.02, -0.03, -0.04]


def test_footprint_moves_into_and_out_of_the_robot_frame():
    moved = transform_footprint((1.0, 2.0, math.pi / 2), SQUARE)
    assert np.allclose(moved[0], (0.9, 2.1))
    back = footprint_to_robot_frame(moved, (1.0, 2.0, math.pi / 2))
    assert np.allclose(back, SQUARE)


def test_world_to_map_truncates_and_refuses_outside():
    assert world_to_map(0.12, 0.26, (0.0, 0.0), 0.05, (10, 10)) == (2, 5)
    assert world_to_map(-0.01, 0.2, (0.0, 0.0), 0.05, (10, 10)) is None
    assert world_to_map(0.5, 0.2, (0.0, 0.0), 0.05, (10, 10)) is None


def test_line_cells_are_bresenhams_with_both_ends():
    assert list(line_cells(0, 0, 3, 0)) == [(0, 0), (1, 0), (2, 0), (3, 0)]
    assert list(line_cells(0, 0, 0, -2)) == [(0, 0), (0, -1), (0, -2)]
    cells = list(line_cells(0, 0, 4, 2))
    assert cells[0] == (0, 0) and cells[-1] == (4, 2) and len(cells) == 5


def test_footprint_cost_is_the_worst_cell_under_the_outline():
    costs = np.zeros((40, 40), dtype=np.uint8)  # 2 m x 2 m from (0, 0)
    costs[20, 20] = LETHAL_OBSTACLE  # inside the footprint below, not on its outline
    costs[25, 10] = 128
    at_centre = transform_footprint((1.02, 1.02, 0.0), SQUARE)
    assert footprint_cost(costs, (0.0, 0.0), 0.05, at_centre) == 0.0
    assert footprint_cost(costs, (0.0, 0.0), 0.05,
                          transform_footprint((0.62, 1.27, 0.0), SQUARE)) == 128.0
    assert footprint_cost(costs, (0.0, 0.0), 0.05,
                          transform_footprint((1.12, 1.02, 0.0), SQUARE)) == LETHAL_OBSTACLE
    off_map = transform_footprint((1.95, 1.0, 0.0), SQUARE)
    assert footprint_cost(costs, (0.0, 0.0), 0.05, off_map) == LETHAL_OBSTACLE


def test_teleop_scale_slows_down_before_a_collision():
    def wall_at(x):
        return lambda pose: pose[0] >= x
    # 0.5 m/s straight on: a wall at 0.3 m is hit after 0.6 s of a 1 s projection
    assert math.isclose(teleop_scale(wall_at(0.3), (0, 0, 0), 0.5, 0, 0, 0.1, 1.0), 0.6)
    assert teleop_scale(wall_at(0.04), (0, 0, 0), 0.5, 0, 0, 0.1, 1.0) == 0.0
    assert teleop_scale(wall_at(5.0), (0, 0, 0), 0.5, 0, 0, 0.1, 1.0) == 1.0
