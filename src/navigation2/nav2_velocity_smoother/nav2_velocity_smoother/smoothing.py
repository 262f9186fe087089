"""The velocity smoother's arithmetic (upstream's findEtaConstraint / applyConstraints).

A step from the current velocity towards the command is bounded per axis by the
acceleration (speed growing, same sign) or the deceleration (slowing down or crossing zero)
times the period. With scale_velocities, the axis furthest from its bound scales the whole
step (eta) so the robot keeps the commanded direction.
"""

from __future__ import annotations

from collections.abc import Sequence


def step_bounds(v_curr: float, v_cmd: float, accel: float, decel: float,
                frequency: float) -> tuple[float, float]:
    """(max, min) change of one axis in one period."""
    if abs(v_cmd) >= abs(v_curr) and v_curr * v_cmd >= 0.0:
        return accel / frequency, -accel / frequency
    return -decel / frequency, decel / frequency


def eta_constraint(v_curr: float, v_cmd: float, accel: float, decel: float,
                   frequency: float) -> float:
    """The scale that brings this axis' step within its bounds, or -1 if it is within."""
    dv = v_cmd - v_curr
    v_max, v_min = step_bounds(v_curr, v_cmd, accel, decel, frequency)
    if dv > v_max:
        return v_max / dv
    if dv < v_min:
        return v_min / dv
    return -1.0


def apply_constraints(v_curr: float, v_cmd: float, accel: float, decel: float, eta: float,
                      frequency: float) -> float:
    dv = v_cmd - v_curr
    v_max, v_min = step_bounds(v_curr, v_cmd, accel, decel, frequency)
    return v_curr + min(max(eta * dv, v_min), v_max)


def smooth(current: Sequence[float], command: Sequence[float], max_accel: Sequence[float],
           max_decel: Sequence[float], frequency: float, scale_velocities: bool) -> list[float]:
    """One period's output (vx, vy, wz) from the current velocity and the clamped command."""
    eta = 1.0
    if scale_velocities:
        for axis in range(3):
            curr_eta = eta_constraint(current[axis], command[axis], max_accel[axis],
                                      max_decel[axis], frequency)
            if curr_eta > 0.0 and abs(1.0 - curr_eta) > abs(1.0 - eta):
                eta = curr_eta
    return [apply_constraints(current[axis], command[axis], max_accel[axis], max_decel[axis],
                              eta, frequency) for axis in range(3)]


def limits_error(max_velocity: Sequence[float], min_velocity: Sequence[float],
                 max_accel: Sequence[float], max_decel: Sequence[float],
                 deadband: Sequence[float]) -> str | None:
    """Upstream's refusal of inconsistent limits, or None when they are usable."""
    if any(len(values) != 3 for values in (max_velocity, min_velocity, max_accel, max_decel,
                                           deadband)):
        return ('Invalid setting of kinematic and/or deadband limits! All limits must be '
                'size of 3 representing (x, y, theta).')
    for axis in range(3):
        if max_decel[axis] > 0.0:
            return ('Positive values set of deceleration! These should be negative to slow '
                    'down!')
        if max_accel[axis] < 0.0:
            return ('Negative values set of acceleration! These should be positive to speed '
                    'up!')
        if min_velocity[axis] > max_velocity[axis]:
            return 'Minimum velocities are higher than maximum velocities!'
    return None
