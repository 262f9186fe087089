"""The controller side's pure maths as plain functions: goal and progress checkers, path
geometry, Regulated Pure Pursuit's regulation, and MPPI's optimizer and critics."""

from __future__ import annotations

import math

import numpy as np
import pytest
from nav2_controller.checkers import SimpleGoalChecker, SimpleProgressChecker, StoppedGoalChecker
from nav2_controller.geometry import (
    closest_index,
    compose,
    first_after_integrated_distance,
    path_length,
    to_frame,
)
from nav2_mppi_controller.critics import CRITICS, CriticData, Grid
from nav2_mppi_controller.optimizer import Optimizer, integrate, read_settings
from nav2_mppi_controller.path_handler import PathHandler
from nav2_regulated_pure_pursuit_controller import regulation as reg


def params(values: dict):
    return lambda key, default: values.get(key, default)


def straight(length: float, step: float = 0.05, y: float = 0.0) -> np.ndarray:
    xs = np.arange(0.0, length + 1e-9, step)
    return np.stack([xs, np.full_like(xs, y), np.zeros_like(xs)], axis=1)


def test_simple_goal_checker_is_stateful_about_xy():
    checker = SimpleGoalChecker(params({'xy_goal_tolerance': 0.25, 'yaw_goal_tolerance': 0.25}))
    goal = (1.0, 0.0, 0.0)
    assert not checker.is_goal_reached((0.7, 0.0, 0.0), goal, (0, 0, 0))
    assert not checker.is_goal_reached((0.9, 0.0, 1.0), goal, (0, 0, 0))  # heading off
    # drifted out of the xy tolerance while turning: stateful, so only the heading counts
    assert checker.is_goal_reached((0.7, 0.0, 0.1), goal, (0, 0, 0))
    checker.reset()
    assert not checker.is_goal_reached((0.7, 0.0, 0.1), goal, (0, 0, 0))


def test_stopped_goal_checker_waits_for_the_robot_to_stop():
    checker = StoppedGoalChecker(params({}))
    assert not checker.is_goal_reached((1.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.3, 0.0, 0.0))
    assert checker.is_goal_reached((1.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.1, 0.0, 0.2))


def test_progress_checker_fails_after_the_time_allowance():
    clock = [0.0]
    checker = SimpleProgressChecker(params({'required_movement_radius': 0.5,
                                            'movement_time_allowance': 10.0}),
                                    lambda: clock[0])
    assert checker.check((0.0, 0.0, 0.0))
    clock[0] = 9.0
    assert checker.check((0.4, 0.0, 0.0))  # not far enough yet, within the allowance
    clock[0] = 10.5
    assert not checker.check((0.4, 0.0, 0.0))
    assert checker.check((0.6, 0.0, 0.0))  # moved: a new baseline


def test_frames_compose_and_invert():
    poses = np.array([[1.0, 0.0, 0.0], [0.0, 2.0, 1.0]])
    frame = (2.0, -1.0, math.pi / 2)
    there = compose(frame, poses)
    assert there[0] == pytest.approx([2.0, 0.0, math.pi / 2])
    assert to_frame(frame, there) == pytest.approx(poses)


def test_path_helpers():
    path = straight(2.0)
    assert path_length(path) == pytest.approx(2.0)
    assert path_length(path, 20) == pytest.approx(1.0)
    assert closest_index(path, 0.52, 0.3) == 10
    assert first_after_integrated_distance(path, 1.0) == 21
    assert first_after_integrated_distance(path, 5.0) == len(path)


def test_rpp_lookahead_point_is_on_the_circle():
    path = straight(2.0, y=0.3)
    x, y, _ = reg.lookahead_point(0.6, path)
    assert math.hypot(x, y) == pytest.approx(0.6)
    assert y == pytest.approx(0.3)
    assert reg.curvature(x, y) == pytest.approx(2 * 0.3 / 0.36)
    assert reg.lookahead_point(5.0, path)[:2] == pytest.approx((2.0, 0.3))  # the last pose


def test_rpp_regulation():
    assert reg.curvature_constraint(0.5, 1 / 0.45, 0.9) == pytest.approx(0.25)
    assert reg.curvature_constraint(0.5, 0.5, 0.9) == 0.5
    # cost 253 at the inscribed radius 0.2: the obstacle is 0.2 m away, within 0.6 m
    assert reg.cost_constraint(0.5, 253.0, 0.2, 3.0, 0.6, 1.0) == pytest.approx(0.5 * 0.2 / 0.6)
    assert reg.cost_constraint(0.5, 0.0, 0.2, 3.0, 0.6, 1.0) == 0.5
    near_end = straight(0.3)
    assert reg.approach_velocity_constraint(0.5, near_end, 0.05, 0.6) == pytest.approx(0.25)
    assert reg.lookahead_distance(0.4, 0.6, True, 1.5, 0.3, 0.9) == pytest.approx(0.6)
    assert reg.lookahead_distance(0.9, 0.6, True, 1.5, 0.3, 0.9) == pytest.approx(0.9)
    cusp = np.concatenate([straight(1.0), straight(1.0)[::-1][1:]])
    assert reg.find_velocity_sign_change(cusp) == pytest.approx(1.0)
    assert reg.find_velocity_sign_change(straight(1.0)) == math.inf
    assert reg.rotate_to_heading(1.0, 0.0, 1.8, 3.2, 0.05) == pytest.approx(0.16)
    assert reg.rotate_to_heading(0.001, 1.0, 1.8, 3.2, 0.05) == pytest.approx(
        math.sqrt(2 * 3.2 * 0.001))


MPPI = {'critics': ['ConstraintCritic', 'CostCritic', 'GoalCritic', 'GoalAngleCritic',
                    'PathAlignCritic', 'PathFollowCritic', 'PathAngleCritic',
                    'PreferForwardCritic'],
        'batch_size': 1000, 'PathAlignCritic.cost_weight': 14.0,
        'PathFollowCritic.offset_from_furthest': 5, 'regenerate_noises': True}


def test_mppi_settings_refuse_a_model_dt_shorter_than_the_period():
    with pytest.raises(ValueError, match='Controller period more then model dt'):
        read_settings(params({'model_dt': 0.02}), 1000, 20.0, print)
    with pytest.raises(ValueError, match='Model Ackermann is not valid'):
        read_settings(params({'motion_model': 'Ackermann'}), 1000, 20.0, print)
    assert read_settings(params({}), 1000, 20.0, print).shift_control_sequence


def test_integrate_moves_along_the_previous_heading():
    vx = np.full((1, 3), 1.0, dtype=np.float32)
    wz = np.full((1, 3), math.pi / 2 / 0.1, dtype=np.float32)  # a quarter turn each step
    x, y, _ = integrate((0.0, 0.0, 0.0), vx, None, wz, 0.1)
    assert x[0] == pytest.approx([0.1, 0.1, 0.0], abs=1e-6)
    assert y[0] == pytest.approx([0.0, 0.1, 0.1], abs=1e-6)


def mppi_step(optimizer, critics, pose, speed, path, goal, grid):
    x, y, yaws = optimizer.rollout(pose, speed)
    data = CriticData(pose, optimizer.v[0], optimizer.v[2], x, y, yaws, path, goal, 0.05, grid,
                      np.zeros(optimizer.s.batch_size, dtype=np.float32))
    for critic in critics:
        critic.score(data)
    optimizer.update(data.costs)
    optimizer.smooth()
    command = optimizer.command()
    optimizer.shift()
    return command, data


def simulate(obstacle: bool) -> tuple[np.ndarray, list]:
    """Drive a perfect unicycle with MPPI along y = 0 towards x = 3 for 4 s."""
    settings = read_settings(params(MPPI), 1000, 20.0, print)
    optimizer = Optimizer(settings, seed=3)
    critics = [CRITICS[c](c, lambda k, d, c=c: MPPI.get(f'{c}.{k}', d), params(MPPI))
               for c in MPPI['critics']]
    costs = np.zeros((120, 120), dtype=np.uint8)  # 6 m x 6 m from (-1.5, -3)
    if obstacle:
        costs[60:68, 40:60] = 150  # inflation round the block: x 0.5..1.5, y 0..0.4
        costs[61:67, 42:58] = 253  # inscribed
        costs[62:66, 44:56] = 254  # a block x 0.7..1.3, y 0.1..0.3: just left of the path
    grid = Grid(costs, -1.5, -3.0, 0.05, False)
    handler = PathHandler(3.0, 1.7)
    plan = straight(3.0)
    handler.set_path(plan)
    pose, speed = (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)
    track, collisions = [], []
    for _ in range(80):
        path = handler.transform_path(pose, (0.0, 0.0, 0.0), (-1.5, -3.0, 4.5, 3.0))
        (vx, _, wz), _ = mppi_step(optimizer, critics, pose, speed, path,
                                      (3.0, 0.0, 0.0), grid)
        x, y, yaw = pose
        pose = (x + vx * 0.05 * math.cos(yaw), y + vx * 0.05 * math.sin(yaw), yaw + wz * 0.05)
        speed = (vx, 0.0, wz)
        track.append(pose)
        collisions.append(grid.lookup(np.array([pose[0]]), np.array([pose[1]]))[0] >= 253)
    return np.array(track), collisions


def test_mppi_follows_a_straight_path():
    track, _ = simulate(obstacle=False)
    assert track[-1, 0] > 1.2  # 4 s at up to 0.5 m/s, accelerating from rest
    assert np.abs(track[:, 1]).max() < 0.1
    assert abs(track[-1, 2]) < 0.2


def test_mppi_passes_an_obstacle_beside_the_path_without_touching_it():
    track, collisions = simulate(obstacle=True)
    assert not any(collisions)
    assert track[-1, 0] > 1.4  # past the block at x 0.7..1.3
