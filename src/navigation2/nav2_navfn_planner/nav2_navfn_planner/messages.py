"""Plans to and from ROS messages: PoseStamped in, nav_msgs/Path out (upstream's poses)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Path

Pose = tuple[float, float, float]


def pose_from_msg(pose: Any) -> Pose:
    """(x, y, yaw) of a geometry_msgs Pose or PoseStamped."""
    pose = getattr(pose, 'pose', pose)
    q = pose.orientation
    yaw = math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))
    return pose.position.x, pose.position.y, yaw


def path_msg(plan: Sequence[Pose], frame_id: str, stamp: Any = None) -> Path:
    """A nav_msgs/Path with one PoseStamped per pose, sharing the path's header."""
    path = Path()
    path.header.frame_id = frame_id
    if stamp is not None:
        path.header.stamp = stamp
    for x, y, yaw in plan:
        pose = PoseStamped()
        pose.header = path.header
        pose.pose.position.x, pose.pose.position.y = float(x), float(y)
        # yaw 0 is the identity quaternion (w = 1), as NavFn's intermediate poses
        pose.pose.orientation.z = math.sin(yaw / 2.0)
        pose.pose.orientation.w = math.cos(yaw / 2.0)
        path.poses.append(pose)
    return path
