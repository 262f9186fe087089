"""slam_toolbox's maths as plain functions: the correlative scan matcher, the pose-graph
optimiser, the occupancy raster, the mapper (scan-to-buffer matching, localization) and the
pose-graph file format."""

from __future__ import annotations

import math

import numpy as np
import pytest
from slam_toolbox_py import serialization
from slam_toolbox_py.mapper import Mapper, MapperParams
from slam_toolbox_py.occupancy import OccupancyMap
from slam_toolbox_py.pose_graph import Edge, compose, optimize, relative
from slam_toolbox_py.scan_matcher import LikelihoodField, SearchWindow, match, transform

LOCAL = SearchWindow(linear=0.25, resolution=0.02, smear=0.05, angular=0.35,
                     angular_step=0.0349, fine_angular_step=0.00349)


def _room_points() -> np.ndarray:
    """The walls of a 6 x 4 m room with a box in it, sampled every 2 cm."""
    t = np.arange(0.0, 1.0, 0.02 / 6)
    walls = [np.stack([-3 + 6 * t, np.full_like(t, -2)], 1),
             np.stack([-3 + 6 * t, np.full_like(t, 2)], 1),
             np.stack([np.full_like(t, -3), -2 + 4 * t], 1),
             np.stack([np.full_like(t, 3), -2 + 4 * t], 1),
             np.stack([1 + 0.5 * t, np.full_like(t, 0.5)], 1),
             np.stack([np.full_like(t, 1), 0.5 + 0.7 * t], 1)]
    return np.concatenate(walls)


def _scan_from(pose: np.ndarray, world: np.ndarray, beams: int = 360) -> np.ndarray:
    """What a 360-beam laser at `pose` sees of the world points: the nearest per beam,
    in the robot's frame."""
    local = (world - pose[:2]) @ np.array([[math.cos(pose[2]), -math.sin(pose[2])],
                                           [math.sin(pose[2]), math.cos(pose[2])]])
    bearing = np.arctan2(local[:, 1], local[:, 0])
    distance = np.hypot(local[:, 0], local[:, 1])
    beam = np.floor((bearing + math.pi) / (2 * math.pi / beams)).astype(int) % beams
    nearest = np.full(beams, np.inf)
    np.minimum.at(nearest, beam, distance)
    angles = -math.pi + (np.arange(beams) + 0.5) * 2 * math.pi / beams
    ok = np.isfinite(nearest)
    return np.stack([nearest[ok] * np.cos(angles[ok]), nearest[ok] * np.sin(angles[ok])], 1)


def test_the_scan_matcher_finds_the_true_pose_from_an_offset_prior():
    world = _room_points()
    field = LikelihoodField.from_points(world, LOCAL.resolution, LOCAL.smear, margin=0.5)
    truth = np.array([0.4, -0.3, 0.2])
    scan = _scan_from(truth, world)
    result = match(field, scan, truth + np.array([0.12, -0.09, -0.1]), LOCAL)
    assert np.hypot(*(result.pose[:2] - truth[:2])) < 0.01, result.pose
    assert abs(result.pose[2] - truth[2]) < 0.005
    assert result.response > 0.9
    assert result.covariance[0, 0] < 0.01 and result.covariance[2, 2] < 0.01


def test_a_scan_of_somewhere_else_has_a_low_response():
    world = _room_points()
    field = LikelihoodField.from_points(world, LOCAL.resolution, LOCAL.smear, margin=0.5)
    elsewhere = transform(_scan_from(np.array([0.0, 0.0, 0.0]), world) * 0.6,
                          np.array([0.0, 0.0, 0.0]))
    result = match(field, elsewhere, np.zeros(3), LOCAL)
    assert result.response < 0.5


def test_the_optimiser_closes_a_square_loop_with_drifting_odometry():
    # Truth: a 4 x 4 m square, nodes every metre; odometry turns 3 % too little, so dead
    # reckoning ends 1 m+ off. One loop edge (last node seen from the first) fixes it.
    truth = [np.array([0.0, 0.0, 0.0])]
    for k in range(16):
        step = np.array([1.0, 0.0, math.pi / 2 if k % 4 == 3 else 0.0])
        truth.append(compose(truth[-1], step))
    truth = np.array(truth)
    odometry = [truth[0]]
    edges = []
    info = np.diag([400.0, 400.0, 1000.0])
    for k in range(16):
        z = relative(truth[k], truth[k + 1])
        drifted = z * np.array([1.0, 1.0, 0.97])
        odometry.append(compose(odometry[-1], drifted))
        edges.append(Edge(k, k + 1, drifted, info))
    odometry = np.array(odometry)
    assert np.hypot(*(odometry[16, :2] - truth[16, :2])) > 0.3
    edges.append(Edge(0, 16, relative(truth[0], truth[16]), info * 10, loop=True))
    solved = optimize(odometry, edges)
    errors = np.hypot(*(solved[:, :2] - truth[:, :2]).T)
    assert errors.max() < 0.15, errors
    assert np.hypot(*(solved[16, :2] - truth[16, :2])) < 0.02
    assert np.allclose(solved[0], truth[0])


def test_the_occupancy_map_marks_hits_occupied_and_rays_free():
    grid = OccupancyMap(resolution=0.05, max_range=20.0)
    pose = np.array([0.0, 0.0, 0.0])
    points = np.array([[2.0, 0.0], [0.0, 1.0], [np.nan, np.nan]])[:2]
    grid.add(0, pose, points)
    grid.add(1, pose, points)
    msg_data, width, height, origin = grid.raster({0: pose, 1: pose})
    data = np.asarray(msg_data).reshape(height, width)

    def at(x: float, y: float) -> int:
        return int(data[int((y - origin[1]) / 0.05), int((x - origin[0]) / 0.05)])

    assert at(2.01, 0.01) == 100
    assert at(1.0, 0.01) == 0
    assert at(0.01, 0.5) == 0
    assert at(1.0, 1.0) == -1


def _mapped_room(tmp_path) -> Mapper:
    """A mapper that drove 1.2 m along x in the room, odometry 5 % long (the first pose
    right: map and room frames are one)."""
    world = _room_points()
    mapper = Mapper(MapperParams(minimum_travel_distance=0.2, minimum_travel_heading=0.2))
    for k in range(7):
        truth = np.array([-1.0 + 0.2 * k, -0.5, 0.0])
        odom = np.array([-1.0 + 0.21 * k, -0.5, 0.0])
        mapper.process(odom, _scan_from(truth, world), np.zeros((0, 2)), np.zeros(2), k)
    return mapper


def test_scan_to_buffer_matching_corrects_the_odometry(tmp_path):
    mapper = _mapped_room(tmp_path)
    assert len(mapper.nodes) == 7
    last = mapper.nodes[-1].pose
    assert np.hypot(last[0] - 0.2, last[1] + 0.5) < 0.02, last  # odometry said 0.26


def test_a_serialized_graph_reads_back_whole_and_localizes(tmp_path):
    mapper = _mapped_room(tmp_path)
    serialization.write(str(tmp_path / 'room'), mapper, 0.05)
    assert (tmp_path / 'room.posegraph').is_file() and (tmp_path / 'room.data').is_file()
    loaded = Mapper(MapperParams(minimum_travel_distance=0.2, minimum_travel_heading=0.2))
    serialization.read(str(tmp_path / 'room.posegraph'), loaded)
    assert len(loaded.nodes) == 7 and len(loaded.edges) == len(mapper.edges)
    for a, b in zip(mapper.nodes, loaded.nodes, strict=True):
        assert np.allclose(a.pose, b.pose) and np.allclose(a.hits, b.hits)
    # localization: start near (not at) the truth, odometry from a new origin
    truth = np.array([0.5, 0.3, 0.3])
    loaded.start_at(truth + np.array([0.1, -0.08, 0.05]))
    pose = loaded.localize(np.zeros(3), _scan_from(truth, _room_points()), 0.0)
    assert np.hypot(*(pose[:2] - truth[:2])) < 0.02 and abs(pose[2] - truth[2]) < 0.01
    assert len(loaded.nodes) == 7  # localization leaves the graph as it was
    assert np.allclose(compose(loaded.map_to_odom(), np.zeros(3)), pose)


def test_a_missing_or_foreign_graph_file_is_refused_and_changes_nothing(tmp_path):
    mapper = _mapped_room(tmp_path)
    before = [n.pose.copy() for n in mapper.nodes]
    with pytest.raises(OSError):
        serialization.read(str(tmp_path / 'nothing_here'), mapper)
    (tmp_path / 'foreign.posegraph').write_text('{"format": "boost archive"}')
    with pytest.raises(ValueError, match='not a slam_toolbox_py pose graph'):
        serialization.read(str(tmp_path / 'foreign'), mapper)
    assert all(np.allclose(n.pose, b) for n, b in zip(mapper.nodes, before, strict=True))
