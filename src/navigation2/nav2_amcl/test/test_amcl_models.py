"""nav2_amcl's pure maths: the map, the motion and laser models, KLD's sample counts."""

from __future__ import annotations

import math

import numpy as np
import pytest
from nav2_amcl.amcl_core import AmclCore
from nav2_amcl.angles import angle_diff
from nav2_amcl.laser_model import (
    LaserParams,
    beam_p,
    beam_subset,
    laser_data,
    likelihood_field_p,
    sensor_p,
)
from nav2_amcl.motion_model import (
    DIFFERENTIAL,
    OMNI,
    MotionNoise,
    odometry_update,
)
from nav2_amcl.occupancy import FREE, OCCUPIED, UNKNOWN, AmclMap, distance_map, occupancy_states
from nav2_amcl.particle_filter import ParticleFilter, resample_limit

QUIET = MotionNoise(0.0, 0.0, 0.0, 0.0, 0.0)


def _room(cells: int = 40, resolution: float = 0.1) -> AmclMap:
    """A square room: a one-cell wall all round, free inside."""
    data = np.zeros((cells, cells), dtype=np.int8)
    data[0, :] = data[-1, :] = data[:, 0] = data[:, -1] = 100
    return AmclMap.from_grid(data.ravel(), cells, cells, resolution, 0.0, 0.0)


def test_occupancy_states_follow_convert_map():
    states = occupancy_states(np.array([0, 100, -1, 50, 99, 1]))
    assert states.tolist() == [FREE, OCCUPIED, UNKNOWN, UNKNOWN, UNKNOWN, UNKNOWN]


def test_distance_map_is_the_exact_capped_euclidean_distance():
    rng = np.random.default_rng(3)
    states = np.where(rng.random((30, 45)) < 0.02, OCCUPIED, FREE).astype(np.int8)
    states[7, 11] = OCCUPIED
    result = distance_map(states, 0.05, 0.6)
    occupied = np.argwhere(states == OCCUPIED)
    rows, cols = np.indices(states.shape)
    brute = np.min(np.hypot(rows[..., None] - occupied[:, 0], cols[..., None] - occupied[:, 1]),
                   axis=-1) * 0.05
    np.testing.assert_allclose(result, np.minimum(brute, 0.6), atol=1e-12)
    assert result[7, 11] == 0.0
    assert distance_map(np.full((4, 4), FREE, np.int8), 0.05, 2.0).max() == 2.0


def test_world_to_map_rounds_as_amcl_and_off_map_is_max_occ_dist():
    amcl_map = _room()
    amcl_map.update_cspace(0.5)
    i, _ = amcl_map.world_to_map(np.array([0.04, 0.05, 0.149]), np.array([0.0, 0.0, 0.0]))
    assert i.tolist() == [0, 1, 1]
    assert amcl_map.map_to_world(3, 4) == pytest.approx((0.3, 0.4))
    assert amcl_map.occ_dist_at(np.array([-5.0, 0.0, 2.0]),
                                np.array([-5.0, 0.0, 2.0])).tolist() == [0.5, 0.0, 0.5]


def test_calc_range_meets_the_walls_of_the_room():
    amcl_map = _room()  # walls at cells 0 and 39: x = 0.0 and x = 3.9
    ranges = amcl_map.calc_range(np.full(4, 2.0), np.full(4, 2.0),
                                 np.array([0.0, np.pi / 2, np.pi, -np.pi / 2]), 10.0)
    np.testing.assert_allclose(ranges, [1.9, 1.9, 2.0, 2.0], atol=1e-9)
    diagonal = amcl_map.calc_range(1.0, 1.0, -3 * np.pi / 4, 20.0)  # to the corner cell
    assert diagonal == pytest.approx(math.hypot(1.0, 1.0), abs=1e-9)
    assert amcl_map.calc_range(2.0, 2.0, 0.0, 0.5) == 0.5  # nothing within max range
    unknown = _room()
    unknown.states[:, 30] = UNKNOWN  # unknown cells stop the ray as upstream's
    assert unknown.calc_range(2.0, 2.0, 0.0, 10.0) == pytest.approx(1.0)


@pytest.mark.parametrize('model', [DIFFERENTIAL, OMNI])
def test_noise_free_motion_moves_each_particle_by_the_odometry(model):
    poses = np.array([[0.0, 0.0, 0.0], [1.0, 2.0, np.pi / 2]])
    old = np.array([5.0, 5.0, 0.0])
    delta = np.array([1.0, 0.0, 0.3])  # 1 m ahead of the odometry's heading, turning 0.3
    odometry_update(model, poses, old, delta, QUIET, np.random.default_rng(0))
    np.testing.assert_allclose(poses, [[1.0, 0.0, 0.3], [1.0, 3.0, np.pi / 2 + 0.3]],
                               atol=1e-12)


def test_omni_model_strafes_in_the_particles_frame():
    poses = np.array([[0.0, 0.0, np.pi / 2]])
    odometry_update(OMNI, poses, np.zeros(3), np.array([0.0, 0.5, 0.0]), QUIET,
                    np.random.default_rng(0))
    np.testing.assert_allclose(poses, [[-0.5, 0.0, np.pi / 2]], atol=1e-12)


def test_differential_spread_grows_with_the_alphas():
    delta = np.array([0.5, 0.1, 0.2])
    spreads = []
    for alpha in (0.01, 0.1, 0.5):
        poses = np.zeros((4000, 3))
        odometry_update(DIFFERENTIAL, poses, np.zeros(3), delta,
                        MotionNoise(alpha, alpha, alpha, alpha), np.random.default_rng(7))
        spreads.append(poses.std(axis=0))
        # the mean still follows the odometry
        assert np.linalg.norm(poses[:, :2].mean(axis=0) - delta[:2]) < 0.05
    assert np.all(spreads[0] < spreads[1]) and np.all(spreads[1] < spreads[2])
    assert spreads[0][0] == pytest.approx(0.1 * 0.51, rel=0.3)  # sqrt(a3) * trans


def test_small_motions_have_no_first_rotation_and_reverse_is_not_a_big_turn():
    poses = np.zeros((1, 3))
    odometry_update(DIFFERENTIAL, poses, np.zeros(3), np.array([0.005, 0.005, 0.0]), QUIET,
                    np.random.default_rng(0))
    np.testing.assert_allclose(poses, [[0.00707107, 0.0, 0.0]], atol=1e-7)
    backwards = np.zeros((3000, 3))
    odometry_update(DIFFERENTIAL, backwards, np.zeros(3), np.array([-0.3, 0.0, 0.0]),
                    MotionNoise(0.2, 0.0, 0.0, 0.0), np.random.default_rng(1))
    # rot1 = pi, but its noise counts as 0: only alpha1 * rot-noise, which is zero here
    assert np.abs(angle_diff(backwards[:, 2], 0.0)).max() < 1e-9
    np.testing.assert_allclose(backwards[:, 0], -0.3, atol=1e-9)


def test_unknown_model_names_the_parameter():
    with pytest.raises(ValueError, match="robot_model_type: 'diff' is not one of"):
        odometry_update('diff', np.zeros((1, 3)), np.zeros(3), np.zeros(3), QUIET,
                        np.random.default_rng(0))


def test_laser_data_limits_and_beam_subset():
    ranges = np.array([0.05, 1.0, np.nan, np.inf, 40.0, 2.0])
    params = LaserParams(laser_max_range=-1.0, laser_min_range=0.1)
    data = laser_data(ranges, -0.5, 0.2, 0.12, 30.0, params)
    assert data.range_max == 30.0
    assert data.ranges[0] == 30.0 and np.isnan(data.ranges[2])
    np.testing.assert_allclose(data.bearings, -0.5 + 0.2 * np.arange(6))
    assert laser_data(ranges, 0.0, 0.1, 0.0, 30.0, LaserParams()).range_max == 30.0
    assert laser_data(ranges, 0.0, 0.1, 0.0, 30.0,
                      LaserParams(laser_max_range=12.0)).range_max == 12.0
    many = laser_data(np.ones(360), 0.0, 0.01, 0.0, 10.0, LaserParams())
    used, bearings = beam_subset(many, 60)  # step (360 - 1) // 59 = 6
    assert used.size == 60 and bearings[1] == pytest.approx(0.06)
    assert beam_subset(many, 1000)[0].size == 360


def test_likelihood_field_known_answer():
    amcl_map = _room()
    amcl_map.update_cspace(2.0)
    params = LaserParams(z_hit=0.5, z_rand=0.5, sigma_hit=0.2)
    data = laser_data(np.array([1.9, 12.0]), 0.0, np.pi / 2, 0.0, 10.0, params)
    # beam 0 ends on the wall (z = 0), beam 1 is at range_max and ignored
    p = likelihood_field_p(amcl_map, np.array([[2.0, 2.0, 0.0]]), np.zeros(3), data, params)
    assert p[0] == pytest.approx(1.0 + (0.5 + 0.5 / 10.0) ** 3)
    off = likelihood_field_p(amcl_map, np.array([[1.7, 2.0, 0.0]]), np.zeros(3), data, params)
    pz = 0.5 * math.exp(-0.3 ** 2 / (2 * 0.2 ** 2)) + 0.05
    assert off[0] == pytest.approx(1.0 + pz ** 3)


@pytest.mark.parametrize('model', ['likelihood_field', 'beam'])
def test_laser_models_prefer_the_true_pose(model):
    amcl_map = _room()
    params = LaserParams(laser_model_type=model, max_beams=30)
    amcl_map.update_cspace(params.laser_likelihood_max_dist)
    truth = np.array([1.2, 2.3, 0.4])
    bearings = np.linspace(-np.pi, np.pi, 181)[:-1]
    ranges = amcl_map.calc_range(truth[0], truth[1], truth[2] + bearings, 8.0)
    data = laser_data(ranges, bearings[0], bearings[1] - bearings[0], 0.0, 8.0, params)
    candidates = truth + np.array([[0.0, 0.0, 0.0], [0.3, 0.0, 0.0], [0.0, -0.3, 0.0],
                                   [0.0, 0.0, 0.3]])
    p = sensor_p(amcl_map, candidates, np.zeros(3), data, params)
    assert np.argmax(p) == 0 and np.all(p[1:] < p[0])
    if model == 'beam':
        assert p[0] == pytest.approx(beam_p(amcl_map, candidates[:1], np.zeros(3), data,
                                            params)[0])
    with pytest.raises(ValueError, match="laser_model_type: 'laser' is not one of"):
        sensor_p(amcl_map, candidates, np.zeros(3), data, LaserParams(laser_model_type='laser'))


def test_resample_limit_known_answers():
    # k = 2: b = 2/9, x = 1 - b + sqrt(b) * 0.99; n = ceil(1 / 0.1 * x^3)
    b = 2 / 9
    expected = math.ceil(1 / (2 * 0.05) * (1 - b + math.sqrt(b) * 0.99) ** 3)
    assert resample_limit(2, 1, 5000, 0.05, 0.99) == expected
    assert resample_limit(1, 500, 2000, 0.05, 0.99) == 2000  # one bin: keep max
    assert resample_limit(3, 500, 2000, 0.05, 0.99) == 500  # clamped to min
    assert resample_limit(10_000, 500, 2000, 0.05, 0.99) == 2000
    counts = resample_limit(np.arange(2, 200), 1, 100_000, 0.05, 0.99)
    assert np.all(np.diff(counts) > 0)


def test_kld_keeps_fewer_particles_for_a_concentrated_cloud():
    counts = []
    for spread in (0.05, 0.5, 3.0):
        pf = ParticleFilter(min_samples=100, max_samples=5000, rng=np.random.default_rng(11))
        pf.init_gaussian(np.array([5.0, 5.0, 0.0]), np.diag([spread ** 2, spread ** 2, 0.1]))
        pf.resample()
        counts.append(pf.sample_count)
    assert counts[0] < counts[1] < counts[2]
    assert counts[0] < 600 and counts[2] == 5000
    # upstream's quirk: a cloud inside a single bin (k = 1) keeps max_particles
    pf = ParticleFilter(min_samples=100, max_samples=5000, rng=np.random.default_rng(11))
    pf.init_gaussian(np.array([5.2, 5.2, 0.05]), np.diag([1e-4, 1e-4, 1e-6]))
    pf.resample()
    assert pf.sample_count == 5000 and len(pf.clusters) == 1


def test_min_particles_above_max_is_refused():
    with pytest.raises(ValueError, match=r'min_particles: 600 must be > 0 and <= max_particles'):
        ParticleFilter(min_samples=600, max_samples=500)


@pytest.mark.parametrize(('params', 'message'), [
    ({'robot_model_type': 'diff'}, "robot_model_type: 'diff' is not one of"),
    ({'laser_model_type': 'likelihood_field_prob'},
     "laser_model_type: 'likelihood_field_prob' is not one of"),
    ({'resample_interval': 0}, 'resample_interval: must be >= 1, got 0'),
    ({'max_beams': 1}, 'max_beams: must be >= 2, got 1'),
    ({'min_particles': 3000}, 'min_particles: 3000 must be > 0 and <= max_particles'),
])
def test_amcl_core_refuses_parameters_it_cannot_run_with(params, message):
    with pytest.raises(ValueError, match=message):
        AmclCore(params)
