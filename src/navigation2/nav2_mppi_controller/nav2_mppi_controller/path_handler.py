"""mppi::PathHandler: the part of the global plan around the robot, in the costmap frame.

Plans are (N, 3) arrays of x, y, yaw. Each cycle the plan is pruned up to the pose nearest
the robot (searched within max_robot_pose_search_dist along the plan), and the next
prune_distance of it, as far as it stays inside the local costmap, is handed to the critics.
"""

from __future__ import annotations

import numpy as np
from nav2_controller.exceptions import InvalidPath
from nav2_controller.geometry import (
    Pose2D,
    closest_index,
    compose,
    first_after_integrated_distance,
    to_frame,
)


class PathHandler:
    def __init__(self, max_robot_pose_search_dist: float, prune_distance: float) -> None:
        self.max_robot_pose_search_dist = max_robot_pose_search_dist
        self.prune_distance = prune_distance
        self.plan = np.zeros((0, 3))

    def set_path(self, plan: np.ndarray) -> None:
        self.plan = np.asarray(plan, dtype=np.float64).reshape(-1, 3)

    def goal(self, plan_to_costmap: Pose2D) -> Pose2D:
        """getTransformedGoal: the plan's last pose in the costmap frame."""
        if len(self.plan) == 0:
            raise InvalidPath('Received plan with zero length')
        return tuple(compose(plan_to_costmap, self.plan[-1:])[0])

    def transform_path(self, pose: Pose2D, plan_to_costmap: Pose2D,
                       bounds: tuple[float, float, float, float]) -> np.ndarray:
        """transformPath: `pose` in the costmap frame; `bounds` the costmap's
        (min_x, min_y, max_x, max_y). Returns the pruned plan in the costmap frame."""
        if len(self.plan) == 0:
            raise InvalidPath('Received plan with zero length')
        robot = to_frame(plan_to_costmap, np.array([pose], dtype=np.float64))[0]
        upper = first_after_integrated_distance(self.plan, self.max_robot_pose_search_dist)
        closest = closest_index(self.plan, robot[0], robot[1], max(upper, 1))
        end = first_after_integrated_distance(self.plan, self.prune_distance, closest)
        local = compose(plan_to_costmap, self.plan[closest:end])
        min_x, min_y, max_x, max_y = bounds
        outside = (local[:, 0] < min_x) | (local[:, 1] < min_y) | (local[:, 0] >= max_x) | \
            (local[:, 1] >= max_y)
        if outside.any():
            local = local[:int(np.argmax(outside))]
        self.plan = self.plan[closest:]
        if len(local) == 0:
            raise InvalidPath('Resulting plan has 0 poses in it.')
        return local
