"""bt_navigator's feedback maths as plain functions: a goal pose into the global frame, the
path length still ahead of the robot, and which goal poses are refused."""

from __future__ import annotations

import math

import pytest
from geometry_msgs.msg import PoseStamped, TransformStamped
from nav2_bt_navigator.navigators import FeedbackUtils, finite, path_remaining, transform_pose
from nav_msgs.msg import Path


def pose(x: float, y: float, yaw: float = 0.0, frame: str = 'map') -> PoseStamped:
    msg = PoseStamped()
    msg.header.frame_id = frame
    msg.pose.position.x, msg.pose.position.y = x, y
    msg.pose.orientation.z, msg.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return msg


class StaticTransforms:
    """A TF buffer's lookup_transform over fixed transforms (target, source) -> (x, y, yaw)."""

    def __init__(self, known: dict[tuple[str, str], tuple[float, float, float]]) -> None:
        self.known = known

    def lookup_transform(self, target: str, source: str, _time, _timeout) -> TransformStamped:
        if (target, source) not in self.known:
            raise LookupError(f'{source} -> {target}')
        x, y, yaw = self.known[(target, source)]
        t = TransformStamped()
        t.transform.translation.x, t.transform.translation.y = x, y
        t.transform.rotation.z, t.transform.rotation.w = math.sin(yaw / 2), math.cos(yaw / 2)
        return t


def yaw(msg: PoseStamped) -> float:
    q = msg.pose.orientation
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def test_a_goal_in_odom_is_turned_and_moved_into_map():
    utils = FeedbackUtils(StaticTransforms({('map', 'odom'): (2.0, 1.0, math.pi / 2)}),
                          'map', 'base_link', 0.1)
    goal = transform_pose(utils, pose(1.0, 0.0, 0.3, 'odom'), 'map')
    assert goal.header.frame_id == 'map'
    assert goal.pose.position.x == pytest.approx(2.0)  # (1, 0) turned a quarter: (0, 1)
    assert goal.pose.position.y == pytest.approx(2.0)
    assert yaw(goal) == pytest.approx(math.pi / 2 + 0.3)
    assert transform_pose(utils, pose(0.0, 0.0, frame='moon'), 'map') is None
    same = pose(1.0, 2.0)
    assert transform_pose(utils, same, 'map') is same


def test_distance_remaining_runs_from_the_path_pose_nearest_the_robot():
    path = Path(poses=[pose(x, 0.0) for x in (0.0, 1.0, 2.0, 3.0)] + [pose(3.0, 2.0)])
    assert path_remaining(path, pose(0.1, 0.2)) == pytest.approx(5.0)
    assert path_remaining(path, pose(1.9, -0.3)) == pytest.approx(3.0)
    assert path_remaining(path, pose(3.1, 2.5)) == 0.0


def test_non_finite_goal_poses_are_refused():
    assert finite(pose(1.0, 2.0))
    assert not finite(pose(float('nan'), 2.0))
    bad = pose(1.0, 2.0)
    bad.pose.orientation.w = float('inf')
    assert not finite(bad)
