"""nav2_core's planner exceptions, each with the error code planner_server answers with.

The codes are those of nav2_msgs' ComputePathToPose (2xx) and ComputePathThroughPoses (3xx)
results; planner_server catches the exception and sets `error_code` and `error_msg`.
"""

from __future__ import annotations

# ComputePathToPose.Result constants; ComputePathThroughPoses adds 100.
NONE = 0
UNKNOWN = 200
INVALID_PLANNER = 201
TF_ERROR = 202
START_OUTSIDE_MAP = 203
GOAL_OUTSIDE_MAP = 204
START_OCCUPIED = 205
GOAL_OCCUPIED = 206
TIMEOUT = 207
NO_VALID_PATH = 208
NO_VIAPOINTS_GIVEN = 309  # ComputePathThroughPoses only


class PlannerException(RuntimeError):
    """nav2_core::PlannerException."""

    code = UNKNOWN
    code_name = 'UNKNOWN'

    def error_code(self, through_poses: bool = False) -> int:
        """The result's error_code for ComputePathToPose (or ComputePathThroughPoses)."""
        if self.code == NO_VIAPOINTS_GIVEN:
            return self.code
        return self.code + 100 if through_poses else self.code


class InvalidPlanner(PlannerException):
    code, code_name = INVALID_PLANNER, 'INVALID_PLANNER'


class StartOccupied(PlannerException):
    code, code_name = START_OCCUPIED, 'START_OCCUPIED'


class GoalOccupied(PlannerException):
    code, code_name = GOAL_OCCUPIED, 'GOAL_OCCUPIED'


class StartOutsideMapBounds(PlannerException):
    code, code_name = START_OUTSIDE_MAP, 'START_OUTSIDE_MAP'


class GoalOutsideMapBounds(PlannerException):
    code, code_name = GOAL_OUTSIDE_MAP, 'GOAL_OUTSIDE_MAP'


class NoValidPathCouldBeFound(PlannerException):
    code, code_name = NO_VALID_PATH, 'NO_VALID_PATH'


class PlannerTimedOut(PlannerException):
    code, code_name = TIMEOUT, 'TIMEOUT'


class PlannerTFError(PlannerException):
    code, code_name = TF_ERROR, 'TF_ERROR'


class NoViapointsGiven(PlannerException):
    code, code_name = NO_VIAPOINTS_GIVEN, 'NO_VIAPOINTS_GIVEN'


class PlannerCancelled(PlannerException):
    """The action was cancelled: planner_server answers no error code for it."""
