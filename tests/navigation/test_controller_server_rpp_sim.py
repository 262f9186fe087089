"""controller_server with Regulated Pure Pursuit driving the MuJoCo diffbot round the
warehouse's centre pillar: the stack of test_controller_server_sim.py on a fresh simulator
(its docstring says why), the plan followed with `controller_id: RPP` and
`goal_checker_id: stopped_goal_checker`."""

from __future__ import annotations

import pytest
from test_controller_server_sim import bring_up, check_arrival, follow, plan, tear_down


@pytest.fixture(scope='module')
def stack(module_launch, module_ros_env, tmp_path_factory, world_map):
    up = bring_up(module_launch, module_ros_env, tmp_path_factory, world_map)
    yield up
    tear_down(up)


@pytest.fixture(scope='module')
def world_map():
    from pathlib import Path

    from ament_index_python.packages import get_package_share_directory
    return Path(get_package_share_directory('mujoco_sim')) / 'maps' / 'warehouse.yaml'


def test_rpp_follows_a_plan_round_the_pillar(stack):
    path = plan(stack, 5.5, 0.25, 0.0)
    assert max(abs(p.pose.position.y - 0.25) for p in path.poses) > 0.4  # round the pillar
    # RPP turns to the goal's heading at up to ~1 rad/s near it: the stopped goal checker
    # waits for the turn to slow down (the general one ends it mid-turn, 0.31 rad past)
    status, result, track, feedback = follow(stack, path, 'RPP', 'stopped_goal_checker')
    print('RPP:', check_arrival(stack, path, status, result, track, feedback))
    stack['controller'].wait_for_output('Reached the goal!')
