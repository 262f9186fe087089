"""Decorators: BT.CPP v4's built-ins and Nav2's RateController, DistanceController,
SpeedController, SingleTrigger and GoalUpdatedController."""

from __future__ import annotations

import math
import time

from nav2_behavior_tree import robot
from nav2_behavior_tree.core import DecoratorNode, InputPort, NodeStatus, is_active, ports, to_float

S, F, R, SKIP = NodeStatus.SUCCESS, NodeStatus.FAILURE, NodeStatus.RUNNING, NodeStatus.SKIPPED


class Inverter(DecoratorNode):
    def tick(self) -> NodeStatus:
        self.status = R
        child_status = self.child.execute_tick()
        if child_status in (S, F):
            self.child.reset_status()
            return F if child_status == S else S
        return child_status


class ForceSuccess(DecoratorNode):
    def tick(self) -> NodeStatus:
        child_status = self.child.execute_tick()
        if child_status in (S, F):
            self.child.reset_status()
            return S
        return child_status


class ForceFailure(DecoratorNode):
    def tick(self) -> NodeStatus:
        child_status = self.child.execute_tick()
        if child_status in (S, F):
            self.child.reset_status()
            return F
        return child_status


class RetryUntilSuccessful(DecoratorNode):
    """Ticks the child again after a failure, num_attempts times in all (-1: forever)."""

    PORTS = ports(num_attempts=InputPort(int, 1, 'Execute again a failing child'))

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.tries = 0

    def tick(self) -> NodeStatus:
        attempts = self.get_input('num_attempts')
        self.status = R
        while attempts == -1 or self.tries < attempts:
            child_status = self.child.execute_tick()
            if child_status == R:
                return R
            self.child.reset_status()
            if child_status == S:
                self.tries = 0
                return S
            if child_status == SKIP:
                return SKIP
            self.tries += 1
        self.tries = 0
        return F

    def halt(self) -> None:
        self.tries = 0
        super().halt()


class Repeat(DecoratorNode):
    PORTS = ports(num_cycles=InputPort(int, 1, 'Repeat a successful child'))

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.repeats = 0

    def tick(self) -> NodeStatus:
        cycles = self.get_input('num_cycles')
        self.status = R
        while cycles == -1 or self.repeats < cycles:
            child_status = self.child.execute_tick()
            if child_status == R:
                return R
            self.child.reset_status()
            if child_status == F:
                self.repeats = 0
                return F
            self.repeats += 1
        self.repeats = 0
        return S

    def halt(self) -> None:
        self.repeats = 0
        super().halt()


class KeepRunningUntilFailure(DecoratorNode):
    def tick(self) -> NodeStatus:
        child_status = self.child.execute_tick()
        if child_status == S:
            self.child.reset_status()
            return R
        if child_status == F:
            self.child.reset_status()
        return child_status


class Timeout(DecoratorNode):
    """Halts the child and fails once `msec` have passed since the first tick."""

    PORTS = ports(msec=InputPort(int, 0, 'After a certain amount of time, halt() the child'))

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.started = 0.0

    def tick(self) -> NodeStatus:
        if not is_active(self.status):
            self.started = time.monotonic()
        self.status = R
        if time.monotonic() - self.started >= self.get_input('msec') / 1000.0:
            self.child.halt_node()
            return F
        child_status = self.child.execute_tick()
        if child_status != R:
            self.child.reset_status()
        return child_status


class RateController(DecoratorNode):
    """Ticks its child at most at `hz` while the child is not running (Nav2)."""

    PORTS = ports(hz=InputPort(to_float, 10.0, 'Rate'))

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.period = 0.1
        self.start = 0.0
        self.first_time = False

    def tick(self) -> NodeStatus:
        if not is_active(self.status):
            self.period = 1.0 / self.get_input('hz')
            self.start = time.monotonic()
            self.first_time = True
        self.status = R
        elapsed = time.monotonic() - self.start
        if self.first_time or self.child.status == R or elapsed >= self.period:
            self.first_time = False
            child_status = self.child.execute_tick()
            if child_status == S:
                self.start = time.monotonic()
            return child_status
        return self.status


class DistanceController(DecoratorNode):
    """Ticks its child each time the robot has moved `distance` metres (Nav2)."""

    PORTS = ports(distance=InputPort(to_float, 1.0, 'Distance'),
             global_frame=InputPort(str, None, 'Global frame'),
             robot_base_frame=InputPort(str, None, 'Robot base frame'))

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.start_pose: tuple[float, float, float] | None = None
        self.first_time = False

    def _pose(self) -> tuple[float, float, float] | None:
        return robot.current_pose(
            self.blackboard, self.get_input('global_frame'), self.get_input('robot_base_frame'))

    def tick(self) -> NodeStatus:
        if not is_active(self.status):
            self.start_pose = self._pose()
            self.first_time = True
        else:
            self.first_time = False
        self.status = R
        pose = self._pose()
        if pose is None or self.start_pose is None:
            return F
        travelled = math.hypot(pose[0] - self.start_pose[0], pose[1] - self.start_pose[1])
        if self.first_time or self.child.status == R or travelled >= self.get_input('distance'):
            child_status = self.child.execute_tick()
            if child_status == S:
                self.start_pose = pose
                return S
            return R if child_status == R else (SKIP if child_status == SKIP else F)
        return self.status


class SpeedController(DecoratorNode):
    """Ticks its child at a rate between min_rate and max_rate, scaled with the robot's
    speed between min_speed and max_speed (the odometry average of bt_navigator)."""

    PORTS = ports(min_rate=InputPort(to_float, 0.1, 'Minimum rate'),
             max_rate=InputPort(to_float, 1.0, 'Maximum rate'),
             min_speed=InputPort(to_float, 0.0, 'Minimum speed'),
             max_speed=InputPort(to_float, 0.5, 'Maximum speed'),
             filter_duration=InputPort(to_float, 0.3, 'Duration (secs) for velocity smoothing'))

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.start = 0.0
        self.period = 1.0
        self.first_tick = False

    def _update_period(self) -> None:
        min_rate, max_rate = self.get_input('min_rate'), self.get_input('max_rate')
        min_speed, max_speed = self.get_input('min_speed'), self.get_input('max_speed')
        speed = robot.current_speed(self.blackboard)
        if max_speed <= min_speed or speed <= min_speed:
            rate = min_rate
        elif speed >= max_speed:
            rate = max_rate
        else:
            rate = min_rate + (max_rate - min_rate) * (speed - min_speed) / (max_speed - min_speed)
        self.period = 1.0 / max(rate, 1e-6)

    def tick(self) -> NodeStatus:
        if not is_active(self.status):
            self.start = time.monotonic()
            self.first_tick = True
            self._update_period()
        self.status = R
        if self.first_tick or self.child.status == R or \
                time.monotonic() - self.start >= self.period:
            self.first_tick = False
            child_status = self.child.execute_tick()
            if child_status == S:
                self.start = time.monotonic()
                self._update_period()
            return child_status
        return self.status


class SingleTrigger(DecoratorNode):
    """Ticks its child once; afterwards FAILURE until halted (Nav2)."""

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.first_time = True

    def tick(self) -> NodeStatus:
        if not is_active(self.status):
            self.first_time = True
        self.status = R
        if self.first_time:
            child_status = self.child.execute_tick()
            if child_status != R:
                self.first_time = False
                self.child.reset_status()
            return child_status
        return F


class GoalUpdatedController(DecoratorNode):
    """Ticks its child only when goal/goals on the blackboard changed (Nav2)."""

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.goal = None
        self.goals = None
        self.goal_was_updated = False

    def tick(self) -> NodeStatus:
        goal = self.blackboard.get('goal')
        goals = self.blackboard.get('goals')
        if not is_active(self.status):
            self.goal, self.goals = goal, goals
            self.goal_was_updated = True
        self.status = R
        if goal != self.goal or goals != self.goals:
            self.goal, self.goals = goal, goals
            self.goal_was_updated = True
        if self.child.status == R or self.goal_was_updated:
            self.goal_was_updated = False
            return self.child.execute_tick()
        return self.status


DECORATOR_NODES = {cls.__name__: cls for cls in (
    Inverter, ForceSuccess, ForceFailure, RetryUntilSuccessful, Repeat,
    KeepRunningUntilFailure, Timeout, RateController, DistanceController, SpeedController,
    SingleTrigger, GoalUpdatedController)}
DECORATOR_NODES['RetryUntilSuccesful'] = RetryUntilSuccessful  # BT.CPP keeps the old typo
