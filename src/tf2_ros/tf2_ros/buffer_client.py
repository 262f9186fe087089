"""BufferClient: lookups answered by a buffer server (the tf2_msgs/action/LookupTransform
action of `ros2 run tf2_ros buffer_server`), for a node that keeps no tf buffer itself.

The calls block until the server answers: the node must be spun by another thread (a
MultiThreadedExecutor, or a spin thread), as with upstream's BufferClient.
"""

from __future__ import annotations

import threading
import warnings
from typing import Any

import builtin_interfaces.msg
from geometry_msgs.msg import TransformStamped
from rclpy.action import ActionClient
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.time import Time
from tf2_msgs.action import LookupTransform
from tf2_msgs.msg import TF2Error
from tf2_py import (
    ConnectivityException,
    ExtrapolationException,
    InvalidArgumentException,
    LookupException,
    TimeoutException,
    TransformException,
)
from tf2_ros.buffer_interface import NO_WAIT, BufferInterface

DEFAULT_PADDING = Duration(seconds=2.0)  # added to a goal's timeout for the round trip

# TF2Error code -> the exception the client raises with the server's error text.
ERRORS = {
    TF2Error.LOOKUP_ERROR: LookupException,
    TF2Error.CONNECTIVITY_ERROR: ConnectivityException,
    TF2Error.EXTRAPOLATION_ERROR: ExtrapolationException,
    TF2Error.INVALID_ARGUMENT_ERROR: InvalidArgumentException,
    TF2Error.TIMEOUT_ERROR: TimeoutException,
}


class BufferClient(BufferInterface):
    """BufferInterface over the LookupTransform action named `ns`."""

    def __init__(self, node: Node, ns: str, check_frequency: float = 10.0,
                 timeout_padding: Duration = DEFAULT_PADDING) -> None:
        BufferInterface.__init__(self)
        self.node = node
        self.action_client = ActionClient(node, LookupTransform, ns)
        # Kept for upstream's signature; the waits here are woken by the answer, not polled.
        self.check_frequency = check_frequency
        self.timeout_padding = timeout_padding

    def lookup_transform(self, target_frame: str, source_frame: str, time: Any,
                         timeout: Duration = NO_WAIT) -> TransformStamped:
        """The transform from source_frame to target_frame at `time` (0: latest), the server
        waiting up to `timeout` for it."""
        if isinstance(time, builtin_interfaces.msg.Time):
            warnings.warn('Passing a builtin_interfaces.msg.Time argument is deprecated, and '
                          'will be removed in the near future. Use rclpy.time.Time instead.',
                          stacklevel=2)
            time = Time.from_msg(time)
        elif not isinstance(time, Time):
            raise TypeError('Must pass a rclpy.time.Time object.')
        goal = LookupTransform.Goal(target_frame=target_frame, source_frame=source_frame,
                                    source_time=time.to_msg(), timeout=timeout.to_msg(),
                                    advanced=False)
        return self._process_goal(goal)

    def lookup_transform_full(self, target_frame: str, target_time: Time, source_frame: str,
                              source_time: Time, fixed_frame: str,
                              timeout: Duration = NO_WAIT) -> TransformStamped:
        """source_frame at source_time into target_frame at target_time, via fixed_frame."""
        goal = LookupTransform.Goal(target_frame=target_frame, source_frame=source_frame,
                                    source_time=source_time.to_msg(), timeout=timeout.to_msg(),
                                    target_time=target_time.to_msg(), fixed_frame=fixed_frame,
                                    advanced=True)
        return self._process_goal(goal)

    def can_transform(self, target_frame: str, source_frame: str, time: Any,
                      timeout: Duration = NO_WAIT) -> bool:
        try:
            self.lookup_transform(target_frame, source_frame, time, timeout)
        except TransformException:
            return False
        return True

    def can_transform_full(self, target_frame: str, target_time: Time, source_frame: str,
                           source_time: Time, fixed_frame: str,
                           timeout: Duration = NO_WAIT) -> bool:
        try:
            self.lookup_transform_full(target_frame, target_time, source_frame, source_time,
                                       fixed_frame, timeout)
        except TransformException:
            return False
        return True

    def _process_goal(self, goal: Any) -> TransformStamped:
        if not self.action_client.server_is_ready():
            raise TimeoutException('The BufferServer is not ready.')
        # The server answers within the goal's timeout; the padding covers the round trip.
        limit = (Duration.from_msg(goal.timeout).nanoseconds
                 + self.timeout_padding.nanoseconds) / 1e9
        goal_handle = self._wait(self.action_client.send_goal_async(goal), limit)
        if goal_handle is None:
            raise TimeoutException('The LookupTransform goal sent to the BufferServer did not '
                                   'come back in the specified time. Something is likely wrong '
                                   'with the server.')
        if not goal_handle.accepted:
            raise TimeoutException('The LookupTransform goal sent to the BufferServer did not '
                                   'come back with accepted status. Something is likely wrong '
                                   'with the server.')
        response = self._wait(goal_handle.get_result_async(), limit)
        if response is None:
            raise TimeoutException('The BufferServer did not send the LookupTransform result in '
                                   'the specified time. Something is likely wrong with the '
                                   'server.')
        return self._process_result(response.result)

    @staticmethod
    def _wait(future: Any, limit: float) -> Any:
        """The future's result, or None when `limit` seconds pass first."""
        done = threading.Event()
        future.add_done_callback(lambda _: done.set())
        if not future.done() and not done.wait(max(limit, 0.0)):
            return None
        return future.result()

    @staticmethod
    def _process_result(result: Any) -> TransformStamped:
        if result is None or result.error is None:
            raise TransformException('The BufferServer returned None for result or '
                                     'result.error!  Something is likely wrong with the server.')
        code = result.error.error
        if code != TF2Error.NO_ERROR:
            raise ERRORS.get(code, TransformException)(result.error.error_string)
        return result.transform

    def destroy(self) -> None:
        """Destroy the action client (the node stays)."""
        self.action_client.destroy()
