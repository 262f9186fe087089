"""`ros2 run nav2_velocity_smoother velocity_smoother`: Nav2's velocity smoother.

A lifecycle node: it takes the controller's commands on `cmd_vel` (remapped to `cmd_vel_nav`
in nav2_bringup) and publishes, every 1/smoothing_frequency s, a command on `cmd_vel_smoothed`
that is clamped to min/max_velocity and reaches the command no faster than max_accel /
max_decel allow, starting from the last output (OPEN_LOOP) or from the odometry averaged over
odom_duration (CLOSED_LOOP). A command older than velocity_timeout is replaced by zero (the
robot decelerates to a stop, then nothing more is published until the next command).
"""

from __future__ import annotations

import math
import sys
from collections import deque
from typing import Any

from geometry_msgs.msg import Twist, TwistStamped
from nav2_util.lifecycle_node import LifecycleNode, run_server
from nav2_util.parameters import declare_checked, warn_unknown_parameters
from nav_msgs.msg import Odometry
from rcl_interfaces.msg import SetParametersResult
from rclpy.clock import Clock, ClockType
from rclpy.duration import Duration
from rclpy.lifecycle import State, TransitionCallbackReturn
from rclpy.parameter import Parameter
from rclpy.time import Time

from nav2_velocity_smoother.smoothing import limits_error, smooth

DEFAULTS: dict[str, Any] = {
    'smoothing_frequency': 20.0,
    'feedback': 'OPEN_LOOP',
    'scale_velocities': False,
    'max_velocity': [0.50, 0.0, 2.5],
    'min_velocity': [-0.50, 0.0, -2.5],
    'max_accel': [2.5, 0.0, 3.2],
    'max_decel': [-2.5, 0.0, -3.2],
    'odom_topic': 'odom',
    'odom_duration': 0.1,
    'deadband_velocity': [0.0, 0.0, 0.0],
    'velocity_timeout': 1.0,
    'use_realtime_priority': False,
    'enable_stamped_cmd_vel': False,
    'stamp_smoothed_velocity_with_smoothing_time': False,
}
LIMITS = ('max_velocity', 'min_velocity', 'max_accel', 'max_decel', 'deadband_velocity')
FEEDBACK = ('OPEN_LOOP', 'CLOSED_LOOP')


def _twist(values: list[float]) -> Twist:
    msg = Twist()
    msg.linear.x, msg.linear.y, msg.angular.z = (float(v) for v in values)
    return msg


class VelocitySmoother(LifecycleNode):
    def __init__(self) -> None:
        super().__init__('velocity_smoother')
        self.get_logger().info('Creating velocity smoother')
        self.p = {name: declare_checked(self, name, value) for name, value in DEFAULTS.items()}
        for name in LIMITS:
            self.p[name] = [float(v) for v in self.p[name]]
        warn_unknown_parameters(self)
        self._handles: list[Any] = []
        self._timer = None
        self._pub = None
        self.command: list[float] | None = None
        self.last_command_time: Time | None = None
        self.last_cmd = [0.0, 0.0, 0.0]
        self.stopped = True
        self._odom: deque[tuple[float, list[float]]] = deque()
        self.add_on_set_parameters_callback(self._on_parameters)

    # --- lifecycle -----------------------------------------------------------------------
    def on_configure(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Configuring velocity smoother')
        error = limits_error(*(self.p[name] for name in LIMITS))
        if error is None and self.p['feedback'] not in FEEDBACK:
            error = f"Invalid feedback_type, options are OPEN_LOOP and CLOSED_LOOP, got " \
                    f"'{self.p['feedback']}'."
        if error is None and not self.p['smoothing_frequency'] > 0.0:
            error = 'smoothing_frequency must be greater than 0.0.'
        if error is not None:
            self.get_logger().error(error)
            return TransitionCallbackReturn.FAILURE
        stamped = self.p['enable_stamped_cmd_vel']
        self._pub = self.create_lifecycle_publisher(
            TwistStamped if stamped else Twist, 'cmd_vel_smoothed', 1)
        self._handles = [self.create_subscription(
            TwistStamped if stamped else Twist, 'cmd_vel', self.on_cmd_vel, 1)]
        if self.p['feedback'] == 'CLOSED_LOOP':
            self._handles.append(self.create_subscription(
                Odometry, self.p['odom_topic'], self.on_odom, 10))
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Activating')
        self._start_timer()
        return super().on_activate(state)

    def on_deactivate(self, state: State) -> TransitionCallbackReturn:
        if self._timer is not None:
            self.destroy_timer(self._timer)
            self._timer = None
        return super().on_deactivate(state)

    def release(self) -> None:
        for handle in self._handles:
            self.destroy_subscription(handle)
        if self._pub is not None:
            self.destroy_lifecycle_publisher(self._pub)
        self._handles, self._pub, self.command = [], None, None

    def _start_timer(self) -> None:
        # upstream's wall timer: the period does not stretch with a slow sim clock
        self._timer = self.create_timer(1.0 / self.p['smoothing_frequency'], self.on_timer,
                                        clock=Clock(clock_type=ClockType.STEADY_TIME))

    # --- inputs --------------------------------------------------------------------------
    def on_cmd_vel(self, msg: Any) -> None:
        twist = msg.twist if isinstance(msg, TwistStamped) else msg
        values = [twist.linear.x, twist.linear.y, twist.angular.z]
        every = [*values, twist.linear.z, twist.angular.x, twist.angular.y]
        if not all(math.isfinite(v) for v in every):
            self.get_logger().error('Velocity message contains NaNs or Infs! Ignoring as invalid!')
            return
        self.command = values
        self.last_command_time = self.get_clock().now()

    def on_odom(self, msg: Odometry) -> None:
        t = Time.from_msg(msg.header.stamp).nanoseconds * 1e-9
        twist = msg.twist.twist
        self._odom.append((t, [twist.linear.x, twist.linear.y, twist.angular.z]))
        while self._odom and self._odom[0][0] < t - self.p['odom_duration']:
            self._odom.popleft()

    def _odom_twist(self) -> list[float]:
        """The odometry's twist averaged over odom_duration (upstream's OdomSmoother)."""
        if not self._odom:
            return list(self.last_cmd)
        n = len(self._odom)
        return [sum(v[axis] for _, v in self._odom) / n for axis in range(3)]

    # --- the smoothing loop ----------------------------------------------------------------
    def on_timer(self) -> None:
        if self.command is None or self._pub is None:
            return  # wait for the first command
        now = self.get_clock().now()
        command = list(self.command)
        if now - self.last_command_time > Duration(seconds=self.p['velocity_timeout']):
            # nothing new: bring the robot to a stop, then stay quiet
            if self.last_cmd == [0.0, 0.0, 0.0] or self.stopped:
                self.stopped = True
                return
            command = [0.0, 0.0, 0.0]
        self.stopped = False
        current = self._odom_twist() if self.p['feedback'] == 'CLOSED_LOOP' \
            else self.last_cmd
        command = [min(max(command[axis], self.p['min_velocity'][axis]),
                       self.p['max_velocity'][axis]) for axis in range(3)]
        out = smooth(current, command, self.p['max_accel'], self.p['max_decel'],
                     self.p['smoothing_frequency'], self.p['scale_velocities'])
        self.last_cmd = out
        out = [0.0 if abs(v) < self.p['deadband_velocity'][axis] else v
               for axis, v in enumerate(out)]
        if self.p['enable_stamped_cmd_vel']:
            msg = TwistStamped()
            msg.header.stamp = (now if self.p['stamp_smoothed_velocity_with_smoothing_time']
                                else self.last_command_time).to_msg()
            msg.twist = _twist(out)
            self._pub.publish(msg)
        else:
            self._pub.publish(_twist(out))

    # --- dynamic parameters ----------------------------------------------------------------
    def _on_parameters(self, parameters: list[Parameter]) -> SetParametersResult:
        changed = dict(self.p)
        for param in parameters:
            if param.name not in DEFAULTS or param.name in (
                    'odom_topic', 'feedback', 'use_realtime_priority', 'enable_stamped_cmd_vel'):
                continue
            value = param.value
            changed[param.name] = [float(v) for v in value] if param.name in LIMITS else value
        error = limits_error(*(changed[name] for name in LIMITS))
        if error is None and not changed['smoothing_frequency'] > 0.0:
            error = 'smoothing_frequency must be greater than 0.0.'
        if error is not None:
            self.get_logger().error(error)
            return SetParametersResult(successful=False, reason=error)
        restart = changed['smoothing_frequency'] != self.p['smoothing_frequency']
        self.p = changed
        if restart and self._timer is not None:
            self.destroy_timer(self._timer)
            self._start_timer()
        return SetParametersResult(successful=True)


def main(args: list[str] | None = None) -> int:
    return run_server(VelocitySmoother, args)


if __name__ == '__main__':
    sys.exit(main())
