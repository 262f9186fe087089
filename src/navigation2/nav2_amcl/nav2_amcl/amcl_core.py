"""What amcl does with each scan (`AmclNode::laserReceived`), without ROS.

The filter moves the particles and weighs them only once the odometry has moved more than
update_min_d in x or y or update_min_a in yaw since the last filter update (or an update is
forced: a new initial pose, request_nomotion_update), resamples every resample_interval-th
such update, and reports the largest cluster's mean with the whole set's covariance.
"""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np

from nav2_amcl.angles import angle_diff, normalize
from nav2_amcl.laser_model import BEAM, LIKELIHOOD_FIELD, LaserData, LaserParams, sensor_p
from nav2_amcl.motion_model import DIFFERENTIAL, OMNI, MotionNoise, odometry_update
from nav2_amcl.occupancy import AmclMap
from nav2_amcl.particle_filter import ParticleFilter


@dataclass
class FilterParams:
    """The filter's part of amcl's parameters, with Nav2 Jazzy's defaults."""

    robot_model_type: str = DIFFERENTIAL
    min_particles: int = 500
    max_particles: int = 2000
    pf_err: float = 0.05
    pf_z: float = 0.99
    recovery_alpha_slow: float = 0.0
    recovery_alpha_fast: float = 0.0
    update_min_d: float = 0.25
    update_min_a: float = 0.2
    resample_interval: int = 1


def _pick(cls: type, values: dict) -> dict:
    names = {item.name for item in fields(cls)}
    return {key: value for key, value in values.items() if key in names}


def check_params(filter_params: FilterParams, laser_params: LaserParams) -> None:
    """ValueError naming the first parameter the filter cannot run with."""
    if filter_params.robot_model_type not in (DIFFERENTIAL, OMNI):
        raise ValueError(f"robot_model_type: '{filter_params.robot_model_type}' is not one "
                         f"of '{DIFFERENTIAL}', '{OMNI}'")
    if laser_params.laser_model_type not in (LIKELIHOOD_FIELD, BEAM):
        raise ValueError(f"laser_model_type: '{laser_params.laser_model_type}' is not one of "
                         f"'{LIKELIHOOD_FIELD}', '{BEAM}' (likelihood_field_prob is not "
                         'implemented here)')
    if filter_params.resample_interval < 1:
        raise ValueError('resample_interval: must be >= 1, got '
                         f'{filter_params.resample_interval}')
    if laser_params.max_beams < 2:
        raise ValueError(f'max_beams: must be >= 2, got {laser_params.max_beams}')
    if filter_params.pf_err <= 0 or laser_params.sigma_hit <= 0:
        raise ValueError('pf_err and sigma_hit: must be > 0, got '
                         f'{filter_params.pf_err} and {laser_params.sigma_hit}')


@dataclass
class Estimate:
    """The published pose: (x, y, yaw) and its 3 x 3 covariance (x, y, yaw)."""

    pose: np.ndarray
    cov: np.ndarray


class AmclCore:
    """The particle filter, its models and amcl's update rules."""

    def __init__(self, params: dict | None = None, seed: int | None = None) -> None:
        values = params or {}
        self.filter_params = FilterParams(**_pick(FilterParams, values))
        self.laser_params = LaserParams(**_pick(LaserParams, values))
        self.noise = MotionNoise(**_pick(MotionNoise, values))
        check_params(self.filter_params, self.laser_params)
        self.rng = np.random.default_rng(seed)
        self.pf = ParticleFilter(
            min_samples=self.filter_params.min_particles,
            max_samples=self.filter_params.max_particles,
            pop_err=self.filter_params.pf_err, pop_z=self.filter_params.pf_z,
            alpha_slow=self.filter_params.recovery_alpha_slow,
            alpha_fast=self.filter_params.recovery_alpha_fast,
            rng=self.rng, random_pose=self.uniform_poses)
        self.map: AmclMap | None = None
        self._free_x = np.zeros(0)
        self._free_y = np.zeros(0)
        self.pf_init = False  # has the filter an odometry pose to measure motion from
        self.pf_odom_pose = np.zeros(3)
        self.force_update = False
        self.resample_count = 0
        self.initialised = False

    def set_map(self, amcl_map: AmclMap) -> None:
        """handleMapMessage: the distance map and the free cells for random poses."""
        amcl_map.update_cspace(self.laser_params.laser_likelihood_max_dist)
        self.map = amcl_map
        self._free_x, self._free_y = amcl_map.free_cells()

    def uniform_poses(self, count: int) -> np.ndarray:
        """uniformPoseGenerator: a random free cell and a yaw in [-pi, pi)."""
        if self._free_x.size == 0:
            raise ValueError('map: no free cell to place a particle in')
        cells = self.rng.integers(0, self._free_x.size, count)
        poses = np.empty((count, 3))
        poses[:, 0] = self._free_x[cells]
        poses[:, 1] = self._free_y[cells]
        poses[:, 2] = self.rng.random(count) * 2 * np.pi - np.pi
        return poses

    def initial_pose(self, pose: np.ndarray, cov: np.ndarray) -> None:
        """handleInitialPose: a Gaussian cloud; the next scan updates without motion."""
        self.pf.init_gaussian(np.asarray(pose, float), np.asarray(cov, float))
        self.pf_init = False
        self.initialised = True

    def global_localization(self) -> None:
        """reinitialize_global_localization: max_particles poses over the free space."""
        self.pf.init_model(self.uniform_poses)
        self.pf_init = False
        self.initialised = True

    def nomotion_update(self) -> None:
        """request_nomotion_update: the next scan updates the filter without motion."""
        self.force_update = True

    def laser_received(self, odom_pose: np.ndarray, data: LaserData,
                       laser_pose: np.ndarray) -> Estimate | None:
        """One scan with the odometry pose at its stamp; the new estimate if one is due.

        None when nothing is to be published: no update (too little motion), or an update
        that did not resample; amcl then only republishes its last transform.
        """
        if self.map is None or not self.initialised:
            return None
        odom_pose = np.asarray(odom_pose, dtype=np.float64)
        update = False
        delta = np.zeros(3)
        if self.pf_init:
            delta[:2] = odom_pose[:2] - self.pf_odom_pose[:2]
            delta[2] = angle_diff(odom_pose[2], self.pf_odom_pose[2])
            update = bool(abs(delta[0]) > self.filter_params.update_min_d
                          or abs(delta[1]) > self.filter_params.update_min_d
                          or abs(delta[2]) > self.filter_params.update_min_a
                          or self.force_update)
            self.force_update = False
            if update:
                odometry_update(self.filter_params.robot_model_type, self.pf.poses,
                                odom_pose - delta, delta, self.noise, self.rng)
        first = not self.pf_init
        if first:
            self.pf_init = True
            self.resample_count = 0
            update = True
        if not update:
            return None
        self.pf_odom_pose = odom_pose.copy()
        factors = sensor_p(self.map, self.pf.poses, np.asarray(laser_pose, float), data,
                           self.laser_params)
        self.pf.update_sensor(factors)
        self.resample_count += 1
        resampled = self.resample_count % self.filter_params.resample_interval == 0
        if resampled:
            self.pf.resample()
        else:
            self.pf.update_cluster_stats()
        return self.estimate() if resampled or first else None

    def estimate(self) -> Estimate | None:
        """getMaxWeightHyp: the heaviest cluster's mean, the whole set's covariance."""
        best = self.pf.best_cluster()
        if best is None:
            return None
        pose = best.mean.copy()
        pose[2] = float(normalize(pose[2]))
        return Estimate(pose, self.pf.cov.copy())
