"""The warehouse world and its map, as Nav2 will use them: the map world_to_map makes from the
world is the one mujoco_sim installs; every pose that nav2_simple_commander's examples and demos
send (Nav2's depot-map coordinates) is free with room for the robot and its inflation, and
reachable from (0, 0); the simulator's own lidar sees walls where the map has them; the robot's
TF tree is odom -> base_footprint -> base_link with /scan in lidar_link."""

from __future__ import annotations

import math
from collections import deque
from pathlib import Path

import numpy as np
import pytest
import yaml
from nav_msgs.msg import Odometry
from rclpy.qos import DurabilityPolicy, QoSProfile
from sensor_msgs.msg import LaserScan
from tf2_msgs.msg import TFMessage

from support import RosProcess, TestNode, executable, leased_domain, ros_environment

# Every pose upstream's nav2_simple_commander (jazzy) scripts use, (x, y) in the map frame.
UPSTREAM_POSES = {
    'initial pose (every script)': (0.0, 0.0),
    'example_nav_to_pose goal': (17.86, -0.77),
    'example_nav_through_poses / example_waypoint_follower goal 1': (10.15, -0.77),
    'example_nav_through_poses / example_waypoint_follower goal 2': (17.86, -0.77),
    'example_nav_through_poses / example_waypoint_follower goal 3': (21.58, -3.5),
    'example_follow_path goal': (7.0, 0.5),
    'demo_recoveries goal': (8.21, 1.3),
    'demo_picking shelf_A': (8.21, 1.3),
    'demo_picking shelf_B': (11.6, 1.3),
    'demo_picking shelf_C': (12.6, 4.0),
    'demo_picking shelf_D': (19.0, 4.0),
    'demo_picking frieght_bay_1': (-6.0, 5.0),
    'demo_picking frieght_bay_2': (-6.0, 0.0),
    'demo_picking frieght_bay_3': (-6.0, -5.0),
    'demo_inspection route 1': (8.21, 1.3),
    'demo_inspection route 2': (8.7, 4.0),
    'demo_inspection route 3': (11.6, 4.0),
    'demo_inspection route 4': (11.6, 1.3),
    'demo_inspection route 5': (12.6, 1.3),
    'demo_inspection route 6': (12.6, 4.0),
    'demo_inspection route 7': (15.27, 1.3),
    'demo_inspection route 8': (16.4, 1.3),
    'demo_inspection route 9': (19.0, 1.3),
    'demo_inspection route 10': (19.0, 4.0),
    'demo_security route 1': (10.15, -0.77),
    'demo_security route 2': (17.86, -0.77),
    'demo_security route 3': (21.58, -3.5),
    'demo_security route 4': (19.4, -6.4),
    'demo_security route 5': (-6.0, 5.0),
}
CLEARANCE = 0.45  # m from any obstacle: the diffbot's radius (0.15 m) and inflation
FREE, OCCUPIED, UNKNOWN = 254, 0, 205


class Map:
    """A map_server map: the YAML's fields and the PGM's cells (row 0 = largest y)."""

    def __init__(self, yaml_path: Path) -> None:
        self.meta = yaml.safe_load(yaml_path.read_text())
        data = (yaml_path.parent / self.meta['image']).read_bytes()
        magic, _comment, size, maxval, pixels = data.split(b'\n', 4)
        assert magic == b'P5' and maxval == b'255'
        self.width, self.height = (int(v) for v in size.split())
        self.cells = np.frombuffer(pixels, dtype=np.uint8).reshape(self.height, self.width)
        self.resolution = self.meta['resolution']
        self.origin = self.meta['origin']

    def cell(self, x: float, y: float) -> tuple[int, int]:
        """(row, column) of a map point."""
        column = int((x - self.origin[0]) / self.resolution)
        row = self.height - 1 - int((y - self.origin[1]) / self.resolution)
        return row, column

    def clearance(self) -> np.ndarray:
        """Each cell's distance to the nearest occupied cell, m (a brute-force transform over
        the occupied cells near it: they are few per window)."""
        reach = math.ceil(CLEARANCE / self.resolution) + 1
        occupied = self.cells == OCCUPIED
        near = np.full(self.cells.shape, np.inf)
        padded = np.pad(occupied, reach, constant_values=False)
        for dr in range(-reach, reach + 1):
            for dc in range(-reach, reach + 1):
                shifted = padded[reach + dr:reach + dr + self.height,
                                 reach + dc:reach + dc + self.width]
                near[shifted] = np.minimum(near[shifted],
                                           math.hypot(dr, dc) * self.resolution)
        return near


@pytest.fixture(scope='module')
def generated(tmp_path_factory) -> Map:
    """The map world_to_map makes from the installed world, run as a user runs it."""
    directory = tmp_path_factory.mktemp('map')
    with leased_domain() as domain:
        tool = RosProcess([executable('mujoco_sim', 'world_to_map'), 'warehouse.xml', '-o',
                           str(directory / 'warehouse')], ros_environment(domain),
                          directory / 'world_to_map.log')
        assert tool.wait(timeout=60) == 0, tool.output
        tool.stop()
    assert tool.output.startswith(f"Wrote {directory / 'warehouse.yaml'} and "), tool.output
    return Map(directory / 'warehouse.yaml')


def test_the_installed_map_is_the_one_the_tool_makes(generated: Map) -> None:
    from ament_index_python.packages import get_package_share_directory
    installed = Path(get_package_share_directory('mujoco_sim')) / 'maps' / 'warehouse.yaml'
    shipped = Map(installed)
    assert shipped.meta == generated.meta == {
        'image': 'warehouse.pgm', 'mode': 'trinary', 'resolution': 0.05,
        'origin': generated.origin, 'negate': 0, 'occupied_thresh': 0.65,
        'free_thresh': 0.196}
    assert np.array_equal(shipped.cells, generated.cells)
    assert set(np.unique(generated.cells)) == {FREE, OCCUPIED, UNKNOWN}
    # The outer walls enclose the free space: unknown only outside them.
    assert (generated.cells[0, :] == UNKNOWN).all() and (generated.cells[:, 0] == UNKNOWN).all()


def test_every_upstream_pose_is_free_and_reachable_from_the_start(generated: Map) -> None:
    clearance = generated.clearance()
    roomy = (generated.cells == FREE) & (clearance >= CLEARANCE)
    for name, (x, y) in UPSTREAM_POSES.items():
        row, column = generated.cell(x, y)
        assert generated.cells[row, column] == FREE, name
        assert clearance[row, column] >= CLEARANCE, \
            f'{name} ({x}, {y}) is {clearance[row, column]:.2f} m from an obstacle'
    # Breadth-first over cells with the same room: the robot and its inflation fit all the
    # way from (0, 0) to each pose.
    reached = np.zeros_like(roomy)
    start = generated.cell(0.0, 0.0)
    reached[start] = True
    queue, steps = deque([start]), 0
    while queue and steps < roomy.size:
        steps += 1
        row, column = queue.popleft()
        for r, c in ((row + 1, column), (row - 1, column), (row, column + 1),
                     (row, column - 1)):
            if 0 <= r < generated.height and 0 <= c < generated.width and roomy[r, c] \
                    and not reached[r, c]:
                reached[r, c] = True
                queue.append((r, c))
    unreached = [name for name, (x, y) in UPSTREAM_POSES.items()
                 if not reached[generated.cell(x, y)]]
    assert not unreached
    # Not the whole floor: the shelves and pillars take room the robot cannot reach.
    assert reached.sum() < 0.9 * (generated.cells == FREE).sum()


def _yaw(q) -> float:
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


def _check_scan(world_map: Map, scan: LaserScan, truth: Odometry) -> None:
    """Every ray ends on an occupied cell (or next to one) and passes no obstacle of the map.

    The map marks a cell occupied when any point of it is inside an obstacle, so a ray that
    grazes a wall or a corner runs through such edge cells; a ray through an obstacle the
    world does not have (a wall's 0.2 m, a shelf, a pillar) meets a cell with no free cell
    around it."""
    x, y = truth.pose.pose.position.x, truth.pose.pose.position.y
    heading = _yaw(truth.pose.pose.orientation)
    ranges = np.array(scan.ranges)
    angles = scan.angle_min + scan.angle_increment * np.arange(len(ranges))
    seen = np.isfinite(ranges)
    assert seen.sum() >= 200, seen.sum()
    near_wall = passes = 0
    for r, a in zip(ranges[seen], angles[seen], strict=True):
        ex, ey = x + r * math.cos(heading + a), y + r * math.sin(heading + a)
        row, column = world_map.cell(ex, ey)
        window = world_map.cells[row - 1:row + 2, column - 1:column + 2]
        near_wall += bool((window == OCCUPIED).any())
        along = np.arange(0.0, r - 2 * world_map.resolution, world_map.resolution)
        cells = [world_map.cell(x + d * math.cos(heading + a), y + d * math.sin(heading + a))
                 for d in along]
        passes += all((world_map.cells[i - 1:i + 2, j - 1:j + 2] == FREE).any()
                      for i, j in cells)
    assert near_wall == seen.sum(), f'{seen.sum() - near_wall} rays end off the map\'s walls'
    assert passes == seen.sum(), f'{seen.sum() - passes} rays cross an obstacle of the map'


def test_the_lidar_sees_the_map_and_the_tf_tree_is_navs(generated: Map, tmp_path: Path) -> None:
    # The launch file at (0, 0) and the simulator alone at two more poses, side by side.
    poses = [(0.0, 0.0, 0.0), (8.21, 1.3, 1.57), (19.4, -6.4, 2.5)]
    with leased_domain() as d0, leased_domain() as d1, leased_domain() as d2:
        domains = (d0, d1, d2)
        processes = [RosProcess(['ros2', 'launch', 'diffbot_bringup', 'diffbot_sim.launch.py',
                                 'world:=warehouse.xml', 'rviz:=false'],
                                ros_environment(d0), tmp_path / 'launch.log')]
        from ament_index_python.packages import get_package_share_directory
        urdf = Path(get_package_share_directory('diffbot_description')) / 'urdf' / \
            'diffbot.urdf'
        world = Path(get_package_share_directory('mujoco_sim')) / 'worlds' / 'warehouse.xml'
        for index, (x, y, yaw) in enumerate(poses[1:], 1):
            params = tmp_path / f'params{index}.yaml'
            params.write_text(yaml.safe_dump({'mujoco_sim': {'ros__parameters': {
                'robot_description': urdf.read_text(), 'world': str(world),
                'x': x, 'y': y, 'yaw': yaw, 'camera': False}}}))
            processes.append(RosProcess([executable('mujoco_sim', 'mujoco_sim'), '--ros-args',
                                         '--params-file', str(params)],
                                        ros_environment(domains[index]),
                                        tmp_path / f'sim{index}.log'))
        probes = [TestNode(domain) for domain in domains]
        try:
            scans = [p.collect(LaserScan, '/scan') for p in probes]
            truths = [p.collect(Odometry, '/ground_truth/odom') for p in probes]
            tf = probes[0].collect(TFMessage, '/tf', 100)
            latched = QoSProfile(depth=100, durability=DurabilityPolicy.TRANSIENT_LOCAL)
            tf_static = probes[0].collect(TFMessage, '/tf_static', latched)
            for probe, scan_list, truth_list in zip(probes, scans, truths, strict=True):
                probe.spin_until(lambda s=scan_list, t=truth_list: len(s) >= 2 and t, 45,
                                 'two scans and the ground truth')
            for (x, y, yaw), scan_list, truth_list in zip(poses, scans, truths, strict=True):
                truth = truth_list[-1]
                assert truth.pose.pose.position.x == pytest.approx(x, abs=0.01)
                assert truth.pose.pose.position.y == pytest.approx(y, abs=0.01)
                assert _yaw(truth.pose.pose.orientation) == pytest.approx(yaw, abs=0.01)
                assert scan_list[-1].header.frame_id == 'lidar_link'
                _check_scan(generated, scan_list[-1], truth)

            def edges() -> set[tuple[str, str]]:
                return {(t.header.frame_id, t.child_frame_id)
                        for m in tf + tf_static for t in m.transforms}
            wanted = {('odom', 'base_footprint'), ('base_footprint', 'base_link'),
                      ('base_link', 'lidar_link'), ('base_link', 'imu_link')}
            probes[0].spin_until(lambda: edges() >= wanted, 20, f'the TF edges {wanted}')
            # base_footprint is the root: nothing else moves base_link.
            assert {parent for parent, child in edges() if child == 'base_link'} == \
                {'base_footprint'}
        finally:
            for probe in probes:
                probe.close()
            for process in processes:
                assert process.stop() == 0, process.output
    assert "Loaded world '" in processes[0].output and 'warehouse.xml' in processes[0].output


def test_world_to_map_refuses_bad_input_in_one_line(tmp_path: Path) -> None:
    cases = {
        'missing': (['nowhere.xml'], "world 'nowhere.xml' does not exist (a path, or a file of "
                    "mujoco_sim's worlds/ folder)"),
        'resolution': (['warehouse.xml', '--resolution', '0'],
                       'resolution is 0; allowed: 0.005 to 1.0 m'),
        'start': (['warehouse.xml', '--start', '3.5', '0.25'],
                  'start (3.5, 0.25) is inside an obstacle; allowed: a free point from which '
                  'the free space is flooded'),
    }
    with leased_domain() as domain:
        runs = {name: RosProcess([executable('mujoco_sim', 'world_to_map'), *args, '-o',
                                  str(tmp_path / name)], ros_environment(domain),
                                 tmp_path / f'{name}.log')
                for name, (args, _) in cases.items()}
        codes = {name: run.wait(timeout=60) for name, run in runs.items()}
        for run in runs.values():
            run.stop()
    for name, (_, message) in cases.items():
        assert codes[name] == 1, runs[name].output
        assert runs[name].output.splitlines() == [f'world_to_map: error: {message}']
    assert not list(tmp_path.glob('*.pgm')) and not list(tmp_path.glob('*.yaml'))
