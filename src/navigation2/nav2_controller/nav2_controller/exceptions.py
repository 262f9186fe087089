"""nav2_core's controller exceptions, each with the FollowPath error code it ends a goal with.

controller_server catches them in its control loop, logs the message, publishes a zero
velocity and aborts the goal with `error_code` and `error_msg` set from the exception.
"""

from __future__ import annotations

# nav2_msgs/action/FollowPath result codes
NONE = 0
UNKNOWN = 100
INVALID_CONTROLLER = 101
TF_ERROR = 102
INVALID_PATH = 103
PATIENCE_EXCEEDED = 104
FAILED_TO_MAKE_PROGRESS = 105
NO_VALID_CONTROL = 106
CONTROLLER_TIMED_OUT = 107


class ControllerException(RuntimeError):
    """nav2_core::ControllerException: anything else that stops a goal (UNKNOWN)."""

    error_code = UNKNOWN


class InvalidController(ControllerException):
    error_code = INVALID_CONTROLLER


class ControllerTFError(ControllerException):
    error_code = TF_ERROR


class InvalidPath(ControllerException):
    error_code = INVALID_PATH


class PatienceExceeded(ControllerException):
    error_code = PATIENCE_EXCEEDED


class FailedToMakeProgress(ControllerException):
    error_code = FAILED_TO_MAKE_PROGRESS


class NoValidControl(ControllerException):
    error_code = NO_VALID_CONTROL


class ControllerTimedOut(ControllerException):
    error_code = CONTROLLER_TIMED_OUT
