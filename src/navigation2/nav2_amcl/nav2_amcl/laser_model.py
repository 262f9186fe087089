"""Laser measurement models (`nav2_amcl::Laser`, `LikelihoodFieldModel`, `BeamModel`).

Both weigh each particle by how well the scan fits the map from the laser's pose on that
particle, summing the cube of each beam's probability onto 1 as upstream does (a heuristic
that keeps one bad beam from zeroing a particle). `laser_model_type` picks the model.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from nav2_amcl.occupancy import AmclMap

LIKELIHOOD_FIELD = 'likelihood_field'
BEAM = 'beam'


@dataclass
class LaserParams:
    """The laser parameters of Nav2's amcl, with its defaults."""

    laser_model_type: str = LIKELIHOOD_FIELD
    max_beams: int = 60
    laser_max_range: float = 100.0  # -1: the scan's range_max
    laser_min_range: float = -1.0  # -1: the scan's range_min
    laser_likelihood_max_dist: float = 2.0
    sigma_hit: float = 0.2
    z_hit: float = 0.5
    z_rand: float = 0.5
    z_short: float = 0.05
    z_max: float = 0.05
    lambda_short: float = 0.1


@dataclass
class LaserData:
    """A scan as the models read it: ranges with their bearings in the base frame."""

    ranges: np.ndarray
    bearings: np.ndarray
    range_max: float


def laser_data(ranges: np.ndarray, angle_min: float, angle_increment: float,
               scan_range_min: float, scan_range_max: float, params: LaserParams) -> LaserData:
    """laserReceived's preprocessing: the limits, and ranges at or below range_min as max.

    `angle_min` is the first beam's bearing in the base frame (the laser's yaw added).
    """
    range_min = max(scan_range_min, params.laser_min_range)
    range_max = scan_range_max
    if params.laser_max_range > 0:
        range_max = min(scan_range_max, params.laser_max_range)
    values = np.asarray(ranges, dtype=np.float64).copy()
    values[values <= range_min] = range_max  # NaN compares false and stays NaN
    bearings = angle_min + np.arange(values.size) * angle_increment
    return LaserData(values, bearings, float(range_max))


def beam_subset(data: LaserData, max_beams: int) -> tuple[np.ndarray, np.ndarray]:
    """Every step-th beam from the first, step = (count - 1) // (max_beams - 1), at least 1."""
    count = data.ranges.size
    step = (count - 1) // (max_beams - 1) if max_beams > 1 else count
    step = max(step, 1)
    return data.ranges[::step], data.bearings[::step]


def laser_poses(poses: np.ndarray, laser_pose: np.ndarray) -> np.ndarray:
    """The laser's pose on each particle (pf_vector_coord_add)."""
    cos_t, sin_t = np.cos(poses[:, 2]), np.sin(poses[:, 2])
    result = np.empty_like(poses)
    result[:, 0] = poses[:, 0] + laser_pose[0] * cos_t - laser_pose[1] * sin_t
    result[:, 1] = poses[:, 1] + laser_pose[0] * sin_t + laser_pose[1] * cos_t
    result[:, 2] = poses[:, 2] + laser_pose[2]
    return result


def likelihood_field_p(amcl_map: AmclMap, poses: np.ndarray, laser_pose: np.ndarray,
                       data: LaserData, params: LaserParams) -> np.ndarray:
    """Each particle's factor p = 1 + sum(pz^3) over the used beams (no max-range beams)."""
    ranges, bearings = beam_subset(data, params.max_beams)
    keep = ~(ranges >= data.range_max) & ~np.isnan(ranges)
    ranges, bearings = ranges[keep], bearings[keep]
    sensor = laser_poses(poses, laser_pose)
    angles = sensor[:, 2:3] + bearings[None, :]
    hit_x = sensor[:, 0:1] + ranges[None, :] * np.cos(angles)
    hit_y = sensor[:, 1:2] + ranges[None, :] * np.sin(angles)
    z = amcl_map.occ_dist_at(hit_x, hit_y)
    pz = (params.z_hit * np.exp(-(z * z) / (2 * params.sigma_hit ** 2))
          + params.z_rand / data.range_max)
    return 1.0 + np.sum(pz ** 3, axis=1)


def beam_p(amcl_map: AmclMap, poses: np.ndarray, laser_pose: np.ndarray, data: LaserData,
           params: LaserParams) -> np.ndarray:
    """The beam model's factor: ray-cast expected ranges against the measured ones."""
    ranges, bearings = beam_subset(data, params.max_beams)
    keep = ~np.isnan(ranges)  # upstream would turn the weight into NaN
    ranges, bearings = ranges[keep], bearings[keep]
    sensor = laser_poses(poses, laser_pose)
    angles = sensor[:, 2:3] + bearings[None, :]
    expected = amcl_map.calc_range(sensor[:, 0:1], sensor[:, 1:2], angles, data.range_max)
    observed = np.broadcast_to(ranges[None, :], expected.shape)
    z = observed - expected
    pz = params.z_hit * np.exp(-(z * z) / (2 * params.sigma_hit ** 2))
    pz = pz + np.where(z < 0, params.z_short * params.lambda_short
                       * np.exp(-params.lambda_short * observed), 0.0)
    pz = pz + np.where(observed == data.range_max, params.z_max, 0.0)
    pz = pz + np.where(observed < data.range_max, params.z_rand / data.range_max, 0.0)
    return 1.0 + np.sum(pz ** 3, axis=1)


def sensor_p(amcl_map: AmclMap, poses: np.ndarray, laser_pose: np.ndarray, data: LaserData,
             params: LaserParams) -> np.ndarray:
    """Dispatch on `laser_model_type` (likelihood_field_prob is not here yet)."""
    if params.laser_model_type == LIKELIHOOD_FIELD:
        return likelihood_field_p(amcl_map, poses, laser_pose, data, params)
    if params.laser_model_type == BEAM:
        return beam_p(amcl_map, poses, laser_pose, data, params)
    raise ValueError(f"laser_model_type: '{params.laser_model_type}' is not one of "
                     f"'{LIKELIHOOD_FIELD}', '{BEAM}'")
