"""planner_server (with its global_costmap) over real DDS, brought up by lifecycle_manager.

A 6 m x 4 m map written here: a border, a wall at x 2.4..2.6 m from the floor up to
y = 2.6 m (the way round is above it), and a solid block at x >= 4.0, y >= 2.4. The robot
stands at (1, 1) (static TF map -> odom -> base_footprint).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from action_msgs.msg import GoalStatus
from geometry_msgs.msg import PoseStamped
from nav2_msgs.action import ComputePathThroughPoses, ComputePathToPose
from nav_msgs.msg import OccupancyGrid
from nav_msgs.msg import Path as PathMsg
from rclpy.action import ActionClient
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

from support import TestNode

RESOLUTION = 0.05
WIDTH, HEIGHT = 120, 80  # cells: 6 m x 4 m
ROBOT = (1.0, 1.0)
LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                     reliability=ReliabilityPolicy.RELIABLE)

PARAMS = """\
planner_server:
  ros__parameters:
    expected_planner_frequency: 20.0
    planner_plugins: ["GridBased"]
    GridBased:
      plugin: "{plugin}"
      tolerance: 0.5
      use_astar: false
      allow_unknown: true
global_costmap:
  global_costmap:
    ros__parameters:
      update_frequency: 2.0
      publish_frequency: 2.0
      global_frame: map
      robot_base_frame: base_footprint
      robot_radius: 0.15
      resolution: 0.05
      track_unknown_space: true
      always_send_full_costmap: true
      plugins: ["static_layer", "obstacle_layer", "inflation_layer"]
      static_layer:
        plugin: "nav2_costmap_2d::StaticLayer"
        map_subscribe_transient_local: true
      obstacle_layer:
        plugin: "nav2_costmap_2d::ObstacleLayer"
        enabled: true
        observation_sources: scan
        scan:
          topic: /scan
          data_type: "LaserScan"
          marking: true
          clearing: true
      inflation_layer:
        plugin: "nav2_costmap_2d::InflationLayer"
        cost_scaling_factor: 3.0
        inflation_radius: 0.55
"""


def occupied() -> np.ndarray:
    """True where the map has a wall; row 0 is y = 0."""
    walls = np.zeros((HEIGHT, WIDTH), dtype=bool)
    walls[0, :] = walls[-1, :] = walls[:, 0] = walls[:, -1] = True
    walls[:52, 48:52] = True  # x 2.4..2.6 m, y 0..2.6 m
    walls[48:, 80:] = True  # the block: x >= 4.0 m, y >= 2.4 m
    return walls


def write_map(directory: Path) -> Path:
    pixels = np.where(occupied(), 0, 254).astype(np.uint8)[::-1]  # image rows run top down
    (directory / 'room.pgm').write_bytes(
        f'P5\n{WIDTH} {HEIGHT}\n255\n'.encode() + pixels.tobytes())
    yaml = directory / 'room.yaml'
    yaml.write_text('image: room.pgm\nmode: trinary\nresolution: 0.05\n'
                    'origin: [0.0, 0.0, 0.0]\nnegate: 0\noccupied_thresh: 0.65\n'
                    'free_thresh: 0.25\n')
    return yaml


def write_params(directory: Path, plugin: str) -> Path:
    path = directory / 'planner.yaml'
    path.write_text(PARAMS.format(plugin=plugin))
    return path


@pytest.fixture(scope='module')
def stack(module_launch, module_ros_env, tmp_path_factory):
    """map_server, static TF, planner_server and lifecycle_manager up; a probe on the domain."""
    directory = tmp_path_factory.mktemp('planner')
    module_launch('nav2_map_server', 'map_server', '--ros-args',
                  '-p', f'yaml_filename:={write_map(directory)}')
    module_launch('tf2_ros', 'static_transform_publisher', '--frame-id', 'map',
                  '--child-frame-id', 'odom')
    module_launch('tf2_ros', 'static_transform_publisher', '--x', str(ROBOT[0]),
                  '--y', str(ROBOT[1]), '--frame-id', 'odom', '--child-frame-id',
                  'base_footprint')
    planner = module_launch('nav2_planner', 'planner_server', '--ros-args', '--params-file',
                            str(write_params(directory, 'nav2_navfn_planner::NavfnPlanner')))
    manager = module_launch('nav2_lifecycle_manager', 'lifecycle_manager', '--ros-args',
                            '-p', "node_names:=['map_server', 'planner_server']",
                            '-p', 'autostart:=true')
    manager.wait_for_output('Managed nodes are active', timeout=40.0)
    probe = TestNode(int(module_ros_env['ROS_DOMAIN_ID']))
    yield planner, probe
    probe.close()


def pose(x: float, y: float, frame: str = 'map') -> PoseStamped:
    msg = PoseStamped()
    msg.header.frame_id = frame
    msg.pose.position.x, msg.pose.position.y = x, y
    msg.pose.orientation.w = 1.0
    return msg


def send(probe: TestNode, action, name: str, goal) -> tuple[int, object]:
    client = ActionClient(probe.node, action, name)
    try:
        assert client.wait_for_server(timeout_sec=15.0), f'{name} did not appear'
        future = client.send_goal_async(goal)
        probe.spin_until(future.done, 10.0, 'the goal to be answered')
        handle = future.result()
        assert handle.accepted
        result = handle.get_result_async()
        probe.spin_until(result.done, 20.0, 'the result')
        return result.result().status, result.result().result
    finally:
        client.destroy()


def test_path_to_pose_goes_round_the_wall_on_free_cells(stack):
    planner, probe = stack
    plans = probe.collect(PathMsg, '/plan')
    goal = ComputePathToPose.Goal(goal=pose(3.3, 1.0), planner_id='GridBased')
    status, result = send(probe, ComputePathToPose, '/compute_path_to_pose', goal)
    assert status == GoalStatus.STATUS_SUCCEEDED, result.error_msg
    assert result.error_code == 0
    xy = np.array([(p.pose.position.x, p.pose.position.y) for p in result.path.poses])
    assert result.path.header.frame_id == 'map'
    assert np.hypot(*(xy[0] - ROBOT)) < 0.1
    assert np.hypot(*(xy[-1] - (3.3, 1.0))) < 0.05
    cells = np.floor(xy / RESOLUTION).astype(int)
    assert not occupied()[cells[:, 1], cells[:, 0]].any()
    crossing = xy[(xy[:, 0] > 2.35) & (xy[:, 0] < 2.65)]
    assert len(crossing) and crossing[:, 1].min() > 2.6 + 0.15  # above the wall, not through
    assert result.planning_time.sec < 1
    planner.wait_for_output(r'Computing path to goal \(3\.30, 1\.00\) from \(1\.00, 1\.00\)')
    probe.spin_until(lambda: len(plans) > 0, 5.0, 'the plan on /plan')
    assert len(plans[-1].poses) == len(result.path.poses)


def test_path_through_poses(stack):
    _planner, probe = stack
    goal = ComputePathThroughPoses.Goal(goals=[pose(1.5, 3.0), pose(3.3, 1.0)])
    status, result = send(probe, ComputePathThroughPoses, '/compute_path_through_poses', goal)
    assert status == GoalStatus.STATUS_SUCCEEDED, result.error_msg
    xy = np.array([(p.pose.position.x, p.pose.position.y) for p in result.path.poses])
    assert np.hypot(*(xy - (1.5, 3.0)).T).min() < 0.05
    assert np.hypot(*(xy[-1] - (3.3, 1.0))) < 0.05


def test_global_costmap_is_inflated_around_walls(stack):
    _planner, probe = stack
    grids = probe.collect(OccupancyGrid, '/global_costmap/costmap', LATCHED)
    probe.spin_until(lambda: len(grids) > 0, 10.0, 'the global costmap')
    grid = grids[-1]
    assert (grid.info.width, grid.info.height) == (WIDTH, HEIGHT)
    costs = np.array(grid.data, dtype=np.int8).reshape(HEIGHT, WIDTH)
    assert (costs[occupied()] == 100).all()
    row = costs[20]  # y = 1.0 m, left of the wall at x cells 48..51
    assert row[47] == 99 and row[46] == 99  # within the robot's radius: inscribed
    assert 0 < row[42] < 99 and row[42] > row[40] > 0  # decaying out to 0.55 m
    assert row[20] == 0  # far from every wall


def test_goal_in_a_wall_has_no_valid_path(stack):
    planner, probe = stack
    goal = ComputePathToPose.Goal(goal=pose(5.0, 3.2))
    status, result = send(probe, ComputePathToPose, '/compute_path_to_pose', goal)
    assert status == GoalStatus.STATUS_ABORTED
    assert result.error_code == ComputePathToPose.Result.NO_VALID_PATH
    assert result.error_msg == 'Failed to create plan with tolerance of: 0.500000'
    planner.wait_for_output(r'GridBased plugin failed to plan from \(1\.00, 1\.00\) to '
                            r'\(5\.00, 3\.20\): "Failed to create plan with tolerance of: '
                            r'0\.500000"')


def test_bad_goals_abort_with_an_error_code(stack):
    planner, probe = stack
    status, result = send(probe, ComputePathToPose, '/compute_path_to_pose',
                          ComputePathToPose.Goal(goal=pose(3.0, 1.0, 'nowhere')))
    assert (status, result.error_code) == (GoalStatus.STATUS_ABORTED,
                                           ComputePathToPose.Result.TF_ERROR)
    planner.wait_for_output("Unable to transform goal pose from frame 'nowhere' into map")
    status, result = send(probe, ComputePathToPose, '/compute_path_to_pose',
                          ComputePathToPose.Goal(goal=pose(math.nan, 1.0)))
    assert (status, result.error_code) == (GoalStatus.STATUS_ABORTED,
                                           ComputePathToPose.Result.GOAL_OUTSIDE_MAP)
    assert result.error_msg == 'goal pose is not finite: (nan, 1.0, yaw 0.0)'
    status, result = send(probe, ComputePathToPose, '/compute_path_to_pose',
                          ComputePathToPose.Goal(goal=pose(3.0, 1.0), planner_id='Smac'))
    assert (status, result.error_code) == (GoalStatus.STATUS_ABORTED,
                                           ComputePathToPose.Result.INVALID_PLANNER)
    planner.wait_for_output('planner Smac is not a valid planner. Planner names are: GridBased')
    assert 'Traceback' not in planner.output


def test_unknown_planner_plugin_fails_configure(launch, tmp_path):
    planner = launch('nav2_planner', 'planner_server', '--ros-args', '--params-file',
                     str(write_params(tmp_path, 'nav2_smac_planner::SmacPlanner2D')),
                     '-p', 'autostart_node:=true')
    planner.wait_for_output(
        r"Failed to create global planner. Exception: Failed to load plugin "
        r"'nav2_smac_planner::SmacPlanner2D' for GridBased.plugin: the planners available are "
        r'nav2_navfn_planner::NavfnPlanner', timeout=20.0)
    planner.wait_for_output('Auto-starting node planner_server failed to configure!')
    assert planner.popen.poll() is None
    assert 'Traceback' not in planner.output


def test_new_goal_preempts_and_cancel_ends_a_waiting_goal(launch, ros_env, tmp_path):
    """No map yet: goals wait for the costmap, so the second finds the first running."""
    launch('tf2_ros', 'static_transform_publisher', '--frame-id', 'map', '--child-frame-id',
           'base_footprint')
    planner = launch('nav2_planner', 'planner_server', '--ros-args', '--params-file',
                     str(write_params(tmp_path, 'nav2_navfn_planner::NavfnPlanner')),
                     '-p', 'autostart_node:=true')
    planner.wait_for_output(r'\[planner_server\]: Activating plugin GridBased', timeout=30.0)
    probe = TestNode(int(ros_env['ROS_DOMAIN_ID']))
    client = ActionClient(probe.node, ComputePathToPose, '/compute_path_to_pose')
    try:
        assert client.wait_for_server(timeout_sec=15.0)
        handles = []
        for x in (3.0, 3.5):
            future = client.send_goal_async(ComputePathToPose.Goal(goal=pose(x, 1.0)))
            probe.spin_until(future.done, 10.0, 'the goal to be answered')
            assert future.result().accepted
            handles.append(future.result())
        first = handles[0].get_result_async()
        probe.spin_until(first.done, 5.0, 'the first goal to end')
        assert first.result().status == GoalStatus.STATUS_ABORTED
        planner.wait_for_output('Preempting the goal with the new goal')
        cancel = handles[1].cancel_goal_async()
        second = handles[1].get_result_async()
        probe.spin_until(lambda: cancel.done() and second.done(), 5.0, 'the cancel')
        assert second.result().status == GoalStatus.STATUS_CANCELED
    finally:
        client.destroy()
        probe.close()
    assert 'Traceback' not in planner.output
