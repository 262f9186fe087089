"""mppi::Optimizer in numpy: sample, roll out, score, and softmax-average control sequences.

Arrays are (batch_size, time_steps) float32, as upstream's xtensor ones. Everything here is
plain maths on arrays; the critics score the rolled-out trajectories (critics.py).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

# Savitzky-Golay quadratic, 9-point coefficients (upstream's savitskyGolayFilter)
SG_FILTER = np.array([-21.0, 14.0, 39.0, 54.0, 59.0, 54.0, 39.0, 14.0, -21.0],
                     dtype=np.float32) / 231.0
MOTION_MODELS = ('DiffDrive', 'Omni')


@dataclass
class Constraints:
    vx_max: float = 0.5
    vx_min: float = -0.35
    vy: float = 0.5
    wz: float = 1.9
    ax_max: float = 3.0
    ax_min: float = -3.0
    ay_max: float = 3.0
    ay_min: float = -3.0
    az_max: float = 3.5


@dataclass
class Settings:
    """OptimizerSettings, read with upstream's names and defaults."""

    model_dt: float = 0.05
    time_steps: int = 56
    batch_size: int = 1000
    iteration_count: int = 1
    temperature: float = 0.3
    gamma: float = 0.015
    vx_std: float = 0.2
    vy_std: float = 0.2
    wz_std: float = 0.4
    retry_attempt_limit: int = 1
    regenerate_noises: bool = False
    motion_model: str = 'DiffDrive'
    shift_control_sequence: bool = False
    base: Constraints = field(default_factory=Constraints)
    constraints: Constraints = field(default_factory=Constraints)

    @property
    def holonomic(self) -> bool:
        return self.motion_model == 'Omni'


def read_settings(param: Callable[[str, Any], Any], default_batch: int,
                  controller_frequency: float, warn: Callable[[str], None]) -> Settings:
    """Optimizer::getParams and setOffset; a bad value raises ValueError naming it."""
    s = Settings()
    s.model_dt = float(param('model_dt', 0.05))
    s.time_steps = int(param('time_steps', 56))
    s.batch_size = int(param('batch_size', default_batch))
    s.iteration_count = int(param('iteration_count', 1))
    s.temperature = float(param('temperature', 0.3))
    s.gamma = float(param('gamma', 0.015))
    b = s.base
    b.vx_max, b.vx_min = float(param('vx_max', 0.5)), float(param('vx_min', -0.35))
    b.vy, b.wz = float(param('vy_max', 0.5)), float(param('wz_max', 1.9))
    b.ax_max, b.ax_min = abs(float(param('ax_max', 3.0))), float(param('ax_min', -3.0))
    b.ay_max, b.ay_min = float(param('ay_max', 3.0)), float(param('ay_min', -3.0))
    b.az_max = float(param('az_max', 3.5))
    s.vx_std, s.vy_std = float(param('vx_std', 0.2)), float(param('vy_std', 0.2))
    s.wz_std = float(param('wz_std', 0.4))
    s.retry_attempt_limit = int(param('retry_attempt_limit', 1))
    s.regenerate_noises = bool(param('regenerate_noises', False))
    s.motion_model = str(param('motion_model', 'DiffDrive'))
    if b.ax_min > 0.0:
        b.ax_min = -b.ax_min
        warn('Sign of the parameter ax_min is incorrect, consider setting it negative.')
    if b.ay_min > 0.0:
        b.ay_min = -b.ay_min
        warn('Sign of the parameter ay_min is incorrect, consider setting it negative.')
    if s.motion_model not in MOTION_MODELS:
        raise ValueError(f'Model {s.motion_model} is not valid! Valid options are '
                         f"{', '.join(MOTION_MODELS)} (Ackermann is not available here)")
    for name in ('time_steps', 'batch_size', 'iteration_count'):
        if getattr(s, name) < 1:
            raise ValueError(f'{name}: must be >= 1, got {getattr(s, name)}')
    if s.time_steps < 2 or not s.model_dt > 0 or not s.temperature > 0:
        raise ValueError('time_steps must be >= 2, model_dt and temperature > 0: got '
                         f'{s.time_steps}, {s.model_dt}, {s.temperature}')
    s.constraints = Constraints(**vars(b))
    period = 1.0 / controller_frequency if controller_frequency > 0 else math.inf
    if period + 1e-6 < s.model_dt:
        warn('Controller period is less then model dt, consider setting it equal')
    elif abs(period - s.model_dt) < 1e-6:
        s.shift_control_sequence = True
    else:
        raise ValueError('Controller period more then model dt, set it equal to model dt')
    return s


class Optimizer:
    """The sampling, rollout and update half of mppi::Optimizer (critics are separate)."""

    def __init__(self, settings: Settings, seed: int | None = None) -> None:
        self.s = settings
        self.rng = np.random.default_rng(seed)
        self.reset()

    def reset(self) -> None:
        s = self.s
        shape = (s.batch_size, s.time_steps)
        self.control = np.zeros((3, s.time_steps), dtype=np.float32)  # vx, vy, wz sequences
        self.history = np.zeros((4, 3), dtype=np.float32)  # the last four commands
        self.noises = np.zeros((3, *shape), dtype=np.float32)
        self._fresh_noises = False
        self.generate_noises()
        self.v = np.zeros((3, *shape), dtype=np.float32)  # vx, vy, wz of each rollout
        self.cv = np.zeros((3, *shape), dtype=np.float32)  # the noised controls

    def generate_noises(self) -> None:
        s = self.s
        shape = (s.batch_size, s.time_steps)
        for axis, std in ((0, s.vx_std), (2, s.wz_std)) + (((1, s.vy_std),)
                                                           if s.holonomic else ()):
            self.noises[axis] = self.rng.standard_normal(shape, dtype=np.float32) * std
        self._fresh_noises = True

    def set_speed_limit(self, speed_limit: float, percentage: bool) -> None:
        b, c = self.s.base, self.s.constraints
        if speed_limit == 0.0:  # nav2_costmap_2d::NO_SPEED_LIMIT
            ratio = 1.0
        elif percentage:
            ratio = speed_limit / 100.0
        else:
            ratio = speed_limit / b.vx_max if b.vx_max else 1.0
        c.vx_max, c.vx_min, c.vy, c.wz = (b.vx_max * ratio, b.vx_min * ratio, b.vy * ratio,
                                          b.wz * ratio)

    # --- rollouts ------------------------------------------------------------------------
    def rollout(self, pose: tuple[float, float, float], speed: tuple[float, float, float]
                ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """generateNoisedTrajectories: noised controls, their velocities after the
        acceleration limits (the motion model), integrated from `pose`: x, y, yaw."""
        s, c = self.s, self.s.constraints
        if s.regenerate_noises and not self._fresh_noises:
            self.generate_noises()
        self._fresh_noises = False
        np.add(self.control[:, None, :], self.noises, out=self.cv)
        v, cv = self.v, self.cv
        v[0, :, 0], v[1, :, 0], v[2, :, 0] = speed[0], speed[1], speed[2]
        dt = s.model_dt
        dvx_max, dvx_min, dwz = dt * c.ax_max, dt * c.ax_min, dt * c.az_max
        dvy_max, dvy_min = dt * c.ay_max, dt * c.ay_min
        axes = (0, 1) if s.holonomic else (0,)
        for j in range(1, s.time_steps):  # each step limited by the one before (predict)
            for axis, hi, lo in ((a, (dvx_max, dvy_max)[a], (dvx_min, dvy_min)[a])
                                 for a in axes):
                last = v[axis, :, j - 1]
                forward = last > 0
                lower = np.where(forward, last + lo, last - hi)
                upper = np.where(forward, last + hi, last - lo)
                np.clip(cv[axis, :, j - 1], lower, upper, out=cv[axis, :, j - 1])
                v[axis, :, j] = cv[axis, :, j - 1]
            last = v[2, :, j - 1]
            np.clip(cv[2, :, j - 1], last - dwz, last + dwz, out=cv[2, :, j - 1])
            v[2, :, j] = cv[2, :, j - 1]
        return integrate(pose, v[0], v[1] if s.holonomic else None, v[2], dt)

    # --- update --------------------------------------------------------------------------
    def update(self, costs: np.ndarray) -> None:
        """updateControlSequence: costs plus the control cost term, softmax over the batch,
        the weighted average of the noised controls, then the sequence constraints."""
        s = self.s
        costs = costs.astype(np.float32, copy=True)
        axes = ((0, s.vx_std), (2, s.wz_std)) + (((1, s.vy_std),) if s.holonomic else ())
        for axis, std in axes:
            bounded = self.cv[axis] - self.control[axis]
            costs += s.gamma / std ** 2 * (bounded @ self.control[axis])
        exponents = np.exp(-(costs - costs.min()) / s.temperature)
        weights = exponents / exponents.sum()
        for axis, _ in axes:
            self.control[axis] = weights @ self.cv[axis]
        self._constrain_sequence()

    def _constrain_sequence(self) -> None:
        """applyControlSequenceConstraints: limits, then acceleration step by step."""
        s, c = self.s, self.s.constraints
        seq = self.control
        seq[0] = np.clip(seq[0], c.vx_min, c.vx_max)
        seq[1] = np.clip(seq[1], -c.vy, c.vy) if s.holonomic else 0.0
        seq[2] = np.clip(seq[2], -c.wz, c.wz)
        dt = s.model_dt
        limits = ((0, dt * c.ax_max, dt * c.ax_min), (1, dt * c.ay_max, dt * c.ay_min))
        vx, vy, wz = seq[0].tolist(), seq[1].tolist(), seq[2].tolist()
        for i in range(1, s.time_steps):
            for values, (_, hi, lo) in ((vx, limits[0]), (vy, limits[1])):
                last = values[i - 1]
                if last > 0:
                    values[i] = min(max(values[i], last + lo), last + hi)
                else:
                    values[i] = min(max(values[i], last - hi), last - lo)
            wz[i] = min(max(wz[i], wz[i - 1] - dt * c.az_max), wz[i - 1] + dt * c.az_max)
        seq[0], seq[1], seq[2] = vx, vy, wz

    def smooth(self) -> None:
        """savitskyGolayFilter over the sequence, with the last four commands before it."""
        n = self.s.time_steps
        if n - 1 < 20:
            return
        padded = np.concatenate([self.history.T, self.control,
                                 np.repeat(self.control[:, -1:], 4, axis=1)], axis=1)
        for axis in range(3):
            self.control[axis, :n - 1] = np.convolve(padded[axis], SG_FILTER[::-1],
                                                     'valid')[:n - 1]
        offset = 1 if self.s.shift_control_sequence else 0
        self.history = np.roll(self.history, -1, axis=0)
        self.history[3] = self.control[:, offset]

    def command(self) -> tuple[float, float, float]:
        """getControlFromSequenceAsTwist: the first (second, when shifting) control."""
        offset = 1 if self.s.shift_control_sequence else 0
        return tuple(float(v) for v in self.control[:, offset])

    def shift(self) -> None:
        """shiftControlSequence: drop the control just sent, repeat the last one."""
        self.control[:, :-1] = self.control[:, 1:].copy()
        self.control[:, -1] = self.control[:, -2]

    def optimal_trajectory(self, pose: tuple[float, float, float]) -> np.ndarray:
        x, y, yaw = integrate(pose, self.control[0][None], self.control[1][None]
                              if self.s.holonomic else None, self.control[2][None],
                              self.s.model_dt)
        return np.stack([x[0], y[0], yaw[0]], axis=1)


def integrate(pose: tuple[float, float, float], vx: np.ndarray, vy: np.ndarray | None,
              wz: np.ndarray, dt: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """integrateStateVelocities: yaw by cumulative sum, each step's motion along the heading
    of the step before (the first along the start heading)."""
    x0, y0, yaw0 = pose
    yaws = np.cumsum(wz * np.float32(dt), axis=1, dtype=np.float32) + np.float32(yaw0)
    cos = np.empty_like(yaws)
    sin = np.empty_like(yaws)
    np.cos(yaws[:, :-1], out=cos[:, 1:])
    np.sin(yaws[:, :-1], out=sin[:, 1:])
    cos[:, 0], sin[:, 0] = math.cos(yaw0), math.sin(yaw0)
    dx = vx * cos
    dy = vx * sin
    if vy is not None:
        dx -= vy * sin
        dy += vy * cos
    x = np.cumsum(dx * np.float32(dt), axis=1, dtype=np.float32) + np.float32(x0)
    y = np.cumsum(dy * np.float32(dt), axis=1, dtype=np.float32) + np.float32(y0)
    return x, y, yaws
