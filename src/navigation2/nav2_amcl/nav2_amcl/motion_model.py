"""Odometry motion models (`nav2_amcl::DifferentialMotionModel`, `OmniMotionModel`).

Each moves every particle by the odometry change between two updates, with noise whose
standard deviations grow with the motion as alpha1..alpha5 say (Probabilistic Robotics'
sample_motion_model_odometry; `robot_model_type` picks the model).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from nav2_amcl.angles import angle_diff

DIFFERENTIAL = 'nav2_amcl::DifferentialMotionModel'
OMNI = 'nav2_amcl::OmniMotionModel'
# Below this translation (m) the heading of the motion is meaningless: no first rotation.
_MIN_TRANS_FOR_ROT1 = 0.01


@dataclass
class MotionNoise:
    """alpha1..alpha5 with Nav2's defaults (0.2 each)."""

    alpha1: float = 0.2
    alpha2: float = 0.2
    alpha3: float = 0.2
    alpha4: float = 0.2
    alpha5: float = 0.2


def _gaussian(rng: np.random.Generator, sigma: float, count: int) -> np.ndarray:
    return rng.normal(0.0, sigma, count) if sigma > 0 else np.zeros(count)


def differential_odometry_update(poses: np.ndarray, old_pose: np.ndarray, delta: np.ndarray,
                                 noise: MotionNoise, rng: np.random.Generator) -> None:
    """Move `poses` (N x 3: x, y, yaw) in place by `delta` = new odom pose - old_pose.

    delta[2] is the heading change already wrapped; old_pose is the odometry pose of the
    last filter update. Rotations near +-pi count as small (the robot may drive backwards).
    """
    count = poses.shape[0]
    trans = float(np.hypot(delta[0], delta[1]))
    if trans < _MIN_TRANS_FOR_ROT1:
        rot1 = 0.0
    else:
        rot1 = float(angle_diff(np.arctan2(delta[1], delta[0]), old_pose[2]))
    rot2 = float(angle_diff(delta[2], rot1))
    rot1_noise = min(abs(float(angle_diff(rot1, 0.0))), abs(float(angle_diff(rot1, np.pi))))
    rot2_noise = min(abs(float(angle_diff(rot2, 0.0))), abs(float(angle_diff(rot2, np.pi))))
    a1, a2, a3, a4 = noise.alpha1, noise.alpha2, noise.alpha3, noise.alpha4
    rot1_hat = angle_diff(rot1, _gaussian(
        rng, np.sqrt(a1 * rot1_noise ** 2 + a2 * trans ** 2), count))
    trans_hat = trans - _gaussian(
        rng, np.sqrt(a3 * trans ** 2 + a4 * rot1_noise ** 2 + a4 * rot2_noise ** 2), count)
    rot2_hat = angle_diff(rot2, _gaussian(
        rng, np.sqrt(a1 * rot2_noise ** 2 + a2 * trans ** 2), count))
    heading = poses[:, 2] + rot1_hat
    poses[:, 0] += trans_hat * np.cos(heading)
    poses[:, 1] += trans_hat * np.sin(heading)
    poses[:, 2] += rot1_hat + rot2_hat


def omni_odometry_update(poses: np.ndarray, old_pose: np.ndarray, delta: np.ndarray,
                         noise: MotionNoise, rng: np.random.Generator) -> None:
    """The holonomic model: translation, strafe (alpha5) and rotation noise, in place."""
    count = poses.shape[0]
    trans = float(np.hypot(delta[0], delta[1]))
    rot = float(delta[2])
    trans_sigma = np.sqrt(noise.alpha3 * trans ** 2 + noise.alpha1 * rot ** 2)
    rot_sigma = np.sqrt(noise.alpha4 * trans ** 2 + noise.alpha2 * rot ** 2)
    strafe_sigma = np.sqrt(noise.alpha1 * rot ** 2 + noise.alpha5 * trans ** 2)
    bearing = angle_diff(np.arctan2(delta[1], delta[0]), old_pose[2]) + poses[:, 2]
    cos_b, sin_b = np.cos(bearing), np.sin(bearing)
    trans_hat = trans + _gaussian(rng, trans_sigma, count)
    rot_hat = rot + _gaussian(rng, rot_sigma, count)
    strafe_hat = _gaussian(rng, strafe_sigma, count)
    poses[:, 0] += trans_hat * cos_b + strafe_hat * sin_b
    poses[:, 1] += trans_hat * sin_b - strafe_hat * cos_b
    poses[:, 2] += rot_hat


def odometry_update(model_type: str, poses: np.ndarray, old_pose: np.ndarray,
                    delta: np.ndarray, noise: MotionNoise, rng: np.random.Generator) -> None:
    """Dispatch on `robot_model_type` (upstream's plugin names)."""
    if model_type == DIFFERENTIAL:
        differential_odometry_update(poses, old_pose, delta, noise, rng)
    elif model_type == OMNI:
        omni_odometry_update(poses, old_pose, delta, noise, rng)
    else:
        raise ValueError(f"robot_model_type: '{model_type}' is not one of "
                         f"'{DIFFERENTIAL}', '{OMNI}'")
