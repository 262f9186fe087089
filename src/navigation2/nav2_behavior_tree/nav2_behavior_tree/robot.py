"""What the nodes ask of the robot, through the blackboard's entries as Nav2 puts them there:
`tf_buffer` (tf2_ros.Buffer), `robot_base_frame`, `global_frame`, `transform_tolerance`,
and `odom_smoother` (anything with a `speed()` in m/s)."""

from __future__ import annotations

import math
from typing import Any

from nav2_behavior_tree.core import Blackboard

Pose2D = tuple[float, float, float]


def yaw_of(q: Any) -> float:
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def lookup(blackboard: Blackboard, target: str, source: str) -> Any | None:
    """The latest transform target <- source, or None."""
    buffer = blackboard.get('tf_buffer')
    if buffer is None:
        return None
    from rclpy.time import Time
    try:
        return buffer.lookup_transform(target, source, Time())
    except Exception:  # tf2's LookupException & co.: no pose this tick
        return None


def current_pose(blackboard: Blackboard, global_frame: str | None = None,
                 robot_frame: str | None = None) -> Pose2D | None:
    """The robot's (x, y, yaw) in the global frame, or None without TF."""
    global_frame = global_frame or blackboard.get('global_frame', 'map')
    robot_frame = robot_frame or blackboard.get('robot_base_frame', 'base_link')
    t = lookup(blackboard, global_frame, robot_frame)
    if t is None:
        return None
    tr = t.transform
    return tr.translation.x, tr.translation.y, yaw_of(tr.rotation)


def transform_pose(blackboard: Blackboard, pose: Any, target: str) -> Pose2D | None:
    """A PoseStamped's (x, y, yaw) in `target`, or None when TF cannot tell."""
    p = pose.pose
    x, y, yaw = p.position.x, p.position.y, yaw_of(p.orientation)
    if pose.header.frame_id == target:
        return x, y, yaw
    t = lookup(blackboard, target, pose.header.frame_id)
    if t is None:
        return None
    tr = t.transform
    theta = yaw_of(tr.rotation)
    c, s = math.cos(theta), math.sin(theta)
    return tr.translation.x + c * x - s * y, tr.translation.y + s * x + c * y, yaw + theta


def current_speed(blackboard: Blackboard) -> float:
    smoother = blackboard.get('odom_smoother')
    return float(smoother.speed()) if smoother is not None else 0.0


def distance(a: Pose2D, b: Pose2D) -> float:
    return math.hypot(a[0] - b[0], a[1] - b[1])


def xy_of(pose: Any) -> tuple[float, float]:
    return pose.pose.position.x, pose.pose.position.y
