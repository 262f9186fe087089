"""`ros2 run tf2_ros buffer_server`: a tf buffer that answers lookups for other nodes.

Node `tf_buffer` listens to /tf and /tf_static into a Buffer of `buffer_size` seconds
(parameter, default 120) and serves the tf2_msgs/action/LookupTransform action
`tf2_buffer_server`, which BufferClient calls (as upstream's C++ buffer server).
A goal is answered as soon as its transform can be looked up, or when its timeout has passed
with the lookup's error (TF2Error code and text).
"""

from __future__ import annotations

import sys

from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.action import ActionServer, CancelResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.duration import Duration
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
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
from tf2_ros.buffer import Buffer
from tf2_ros.transform_listener import TransformListener

ACTION_NAME = 'tf2_buffer_server'
# Goals wait on threads of their own (a wait is woken by new data from the listener's thread):
# this many lookups can wait at once.
WAITING_GOALS = 8
ERROR_CODES = (  # most specific first: the first class the exception is an instance of
    (ConnectivityException, TF2Error.CONNECTIVITY_ERROR),
    (LookupException, TF2Error.LOOKUP_ERROR),
    (ExtrapolationException, TF2Error.EXTRAPOLATION_ERROR),
    (InvalidArgumentException, TF2Error.INVALID_ARGUMENT_ERROR),
    (TimeoutException, TF2Error.TIMEOUT_ERROR),
    (TransformException, TF2Error.TRANSFORM_ERROR),
)


class BufferServer(Node):
    def __init__(self) -> None:
        super().__init__('tf_buffer')
        buffer_size = self.declare_parameter('buffer_size', 120.0).value
        self.buffer = Buffer(cache_time=Duration(seconds=buffer_size), node=self)
        # On its own thread, so that transforms keep arriving while goals wait.
        self.listener = TransformListener(self.buffer, self, spin_thread=True)
        self.action_server = ActionServer(
            self, LookupTransform, ACTION_NAME, self.execute,
            cancel_callback=lambda _goal: CancelResponse.ACCEPT,
            callback_group=ReentrantCallbackGroup())

    def execute(self, goal_handle) -> LookupTransform.Result:
        goal = goal_handle.request
        result = LookupTransform.Result()
        timeout = Duration.from_msg(goal.timeout)
        try:
            if goal.advanced:
                args = (goal.target_frame, goal.target_time, goal.source_frame,
                        goal.source_time, goal.fixed_frame)
                self.buffer.can_transform_full(*args, timeout)
                result.transform = self.buffer.lookup_transform_full_core(*args)
            else:
                args = (goal.target_frame, goal.source_frame, goal.source_time)
                self.buffer.can_transform(*args, timeout)
                result.transform = self.buffer.lookup_transform_core(*args)
        except TransformException as error:
            result.error.error = next(code for cls, code in ERROR_CODES
                                      if isinstance(error, cls))
            result.error.error_string = str(error)
            goal_handle.abort()
            return result
        goal_handle.succeed()
        return result


def main(argv: list[str] | None = None) -> int:
    with ros_session(sys.argv if argv is None else argv) as stop:
        spin_until_stopped(BufferServer(), stop, MultiThreadedExecutor(num_threads=WAITING_GOALS))
    return 0


if __name__ == '__main__':
    sys.exit(main())
