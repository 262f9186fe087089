"""The two navigators: NavigateToPoseNavigator and NavigateThroughPosesNavigator.

Each owns a BtActionServer (its action and tree), puts the goal on the blackboard (in the
global frame), and fills the feedback as upstream: the robot's pose from TF, navigation
time, distance remaining along the blackboard's path from its pose nearest the robot, time
remaining from the smoothed odometry speed, the recoveries counted by the tree, and for
through-poses the goals still ahead.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from ament_index_python.packages import get_package_share_directory
from geometry_msgs.msg import PoseStamped
from nav2_msgs.action import NavigateThroughPoses, NavigateToPose
from rclpy.action import ActionClient
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.time import Time

from nav2_bt_navigator.bt_action_server import BtActionServer

FEEDBACK_PERIOD = 0.05  # s: feedback at most at 20 Hz (upstream sends one each 10 ms loop)


@dataclass
class FeedbackUtils:
    tf: Any
    global_frame: str
    robot_frame: str
    transform_tolerance: float


class Muxer:
    """Only one navigator runs at a time (upstream's NavigatorMuxer)."""

    def __init__(self) -> None:
        self.navigators: list[Navigator] = []

    def busy_other(self, me: Navigator) -> Navigator | None:
        return next((n for n in self.navigators if n is not me and n.server.busy()), None)


def transform_pose(utils: FeedbackUtils, pose: PoseStamped, frame: str) -> PoseStamped | None:
    if pose.header.frame_id == frame:
        return pose
    try:
        t = utils.tf.lookup_transform(frame, pose.header.frame_id, Time(),
                                      Duration(seconds=utils.transform_tolerance))
    except Exception:  # tf2's LookupException & co.: the caller says what failed
        return None
    tr, q = t.transform, t.transform.rotation
    theta = math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))
    c, s = math.cos(theta), math.sin(theta)
    x, y = pose.pose.position.x, pose.pose.position.y
    out = PoseStamped()
    out.header.frame_id, out.header.stamp = frame, pose.header.stamp
    out.pose.position.x = tr.translation.x + c * x - s * y
    out.pose.position.y = tr.translation.y + s * x + c * y
    out.pose.position.z = pose.pose.position.z
    o = pose.pose.orientation
    # rotate the goal's orientation by the frame's yaw (z rotation composed with q)
    hz, hw = math.sin(theta / 2), math.cos(theta / 2)
    out.pose.orientation.w = hw * o.w - hz * o.z
    out.pose.orientation.x = hw * o.x - hz * o.y
    out.pose.orientation.y = hw * o.y + hz * o.x
    out.pose.orientation.z = hw * o.z + hz * o.w
    return out


def current_pose(utils: FeedbackUtils, clock: Any) -> PoseStamped | None:
    robot = PoseStamped()
    robot.header.frame_id = utils.robot_frame
    robot.pose.orientation.w = 1.0
    pose = transform_pose(utils, robot, utils.global_frame)
    if pose is not None:
        pose.header.stamp = clock.now().to_msg()
    return pose


def finite(pose: PoseStamped) -> bool:
    p, o = pose.pose.position, pose.pose.orientation
    return all(math.isfinite(v) for v in (p.x, p.y, p.z, o.x, o.y, o.z, o.w))


def path_remaining(path: Any, pose: PoseStamped) -> float:
    """Length of the path from its pose nearest the robot to its end."""
    xy = np.array([(p.pose.position.x, p.pose.position.y) for p in path.poses])
    here = np.array([pose.pose.position.x, pose.pose.position.y])
    nearest = int(np.argmin(np.hypot(*(xy - here).T)))
    return float(np.hypot(*np.diff(xy[nearest:], axis=0).T).sum())


class Navigator:
    ACTION: Any = None
    NAME = ''
    BT_PARAMETER = ''
    DEFAULT_TREE = ''

    def __init__(self, node: Any, name: str, settings: dict[str, Any],
                 blackboard: dict[str, Any], utils: FeedbackUtils, odom: Any,
                 muxer: Muxer) -> None:
        self.node, self.name, self.utils, self.odom, self.muxer = node, name, utils, odom, muxer
        self.logger = node.get_logger()
        self.clock = node.get_clock()
        self.start_time = self.clock.now()
        self.last_feedback = 0.0
        default_bt = settings[self.BT_PARAMETER] or default_tree(self.DEFAULT_TREE)
        self.server = BtActionServer(node, self.ACTION, name, settings, blackboard, default_bt,
                                     self.goal_received, self.on_loop, self.on_preempt,
                                     self.may_accept)
        self.path_key = settings['path_blackboard_id']
        muxer.navigators.append(self)

    def may_accept(self) -> bool:
        other = self.muxer.busy_other(self)
        if other is not None:
            self.logger.error(f'Requested navigation from {self.name} while another navigator '
                              f'is processing, rejecting request.')
            return False
        return True

    def goal_received(self, goal: Any) -> bool:
        if not self.server.load_behavior_tree(goal.behavior_tree):
            self.logger.error(f'BT file not found: {goal.behavior_tree}. Navigation canceled.')
            return False
        return self.initialize_goal(goal)

    def goal_in_global_frame(self, pose: PoseStamped) -> PoseStamped | None:
        if not finite(pose):
            p = pose.pose.position
            self.fail(f'Goal pose ({p.x}, {p.y}) in frame \'{pose.header.frame_id}\' is not '
                      'finite: every position and orientation field must be a number')
            return None
        goal = transform_pose(self.utils, pose, self.utils.global_frame)
        if goal is None:
            self.fail(f"Failed to transform a goal pose provided with frame_id "
                      f"'{pose.header.frame_id}' to the global frame "
                      f"'{self.utils.global_frame}'.")
        return goal

    def fail(self, line: str) -> None:
        self.logger.error(line)
        self.server.error_msg = line

    def robot_pose(self) -> PoseStamped | None:
        return current_pose(self.utils, self.clock)

    def on_preempt(self, goal: Any) -> None:
        self.logger.info('Received goal preemption request')
        same = goal.behavior_tree == self.server.current_bt or (
            not goal.behavior_tree and self.server.current_bt == self.server.default_bt)
        if not same:
            self.logger.warning(
                'Preemption request was rejected since the requested BT XML file is not the '
                'same as the one that the current goal is executing. Preemption with a new BT '
                'is invalid since it would require cancellation of the previous goal instead '
                'of true preemption.\nCancel the current goal and send a new action request if '
                'you want to use a different BT XML file. For now, continuing to track the last '
                'goal until completion.')
            self.server.terminate_pending_goal()
            return
        pending = self.server.pending
        if not self.initialize_goal(pending.request, check_only=True):
            self.logger.warning(
                'Preemption request was rejected since the goal pose could not be transformed. '
                'For now, continuing to track the last goal until completion.')
            self.server.terminate_pending_goal()
            return
        self.initialize_goal(self.server.accept_pending_goal().request)

    def on_loop(self) -> None:
        now = self.clock.now()
        if (now.nanoseconds - self.last_feedback) / 1e9 < FEEDBACK_PERIOD:
            return
        self.last_feedback = now.nanoseconds
        pose = self.robot_pose()
        if pose is None:
            self.logger.error('Robot pose is not available.')
            return
        feedback = self.ACTION.Feedback()
        board = self.server.blackboard
        path = board.get(self.path_key)
        if path is not None and path.poses:
            remaining = path_remaining(path, pose)
            speed = self.odom.speed()
            feedback.distance_remaining = remaining
            if abs(speed) > 0.01 and remaining > 0.1:
                feedback.estimated_time_remaining = Duration(
                    seconds=remaining / abs(speed)).to_msg()
        feedback.number_of_recoveries = int(board.get('number_recoveries', 0))
        feedback.current_pose = pose
        feedback.navigation_time = (now - self.start_time).to_msg()
        self.fill_feedback(feedback)
        self.server.publish_feedback(feedback)

    def fill_feedback(self, feedback: Any) -> None:
        """What one navigator adds to the feedback."""

    def initialize_goal(self, goal: Any, check_only: bool = False) -> bool:
        raise NotImplementedError

    def begin(self, robot: PoseStamped, last: PoseStamped) -> None:
        self.logger.info(
            f'Begin navigating from current location ({robot.pose.position.x:.2f}, '
            f'{robot.pose.position.y:.2f}) to ({last.pose.position.x:.2f}, '
            f'{last.pose.position.y:.2f})')
        self.start_time = self.clock.now()
        self.server.blackboard.set('number_recoveries', 0)


class NavigateToPoseNavigator(Navigator):
    ACTION = NavigateToPose
    BT_PARAMETER = 'default_nav_to_pose_bt_xml'
    DEFAULT_TREE = 'navigate_to_pose_w_replanning_and_recovery.xml'

    def __init__(self, node: Any, name: str, settings: dict[str, Any], *args: Any) -> None:
        super().__init__(node, name, settings, *args)
        self.goal_key = settings['goal_blackboard_id']
        self.self_client = ActionClient(node, NavigateToPose, name)
        self.goal_sub = node.create_subscription(PoseStamped, 'goal_pose', self.on_goal_pose,
                                                 10)

    def initialize_goal(self, goal: Any, check_only: bool = False) -> bool:
        robot = self.robot_pose()
        if robot is None:
            self.fail('Initial robot pose is not available.')
            return False
        pose = self.goal_in_global_frame(goal.pose)
        if pose is None or check_only:
            return pose is not None
        self.begin(robot, pose)
        self.server.blackboard.set(self.goal_key, pose)
        return True

    def on_goal_pose(self, pose: PoseStamped) -> None:
        """A goal from RViz's "2D Goal Pose" navigates as an action goal would."""
        self.self_client.send_goal_async(NavigateToPose.Goal(pose=pose))

    def close(self) -> None:
        self.self_client.destroy()
        self.node.destroy_subscription(self.goal_sub)


class NavigateThroughPosesNavigator(Navigator):
    ACTION = NavigateThroughPoses
    BT_PARAMETER = 'default_nav_through_poses_bt_xml'
    DEFAULT_TREE = 'navigate_through_poses_w_replanning_and_recovery.xml'

    def __init__(self, node: Any, name: str, settings: dict[str, Any], *args: Any) -> None:
        super().__init__(node, name, settings, *args)
        self.goals_key = settings['goals_blackboard_id']

    def initialize_goal(self, goal: Any, check_only: bool = False) -> bool:
        robot = self.robot_pose()
        if robot is None:
            self.fail('Initial robot pose is not available.')
            return False
        poses = []
        for pose in goal.poses:
            transformed = self.goal_in_global_frame(pose)
            if transformed is None:
                return False
            poses.append(transformed)
        if check_only:
            return True
        if poses:
            self.begin(robot, poses[-1])
        self.server.blackboard.set(self.goals_key, poses)
        return True

    def fill_feedback(self, feedback: Any) -> None:
        feedback.number_of_poses_remaining = len(
            self.server.blackboard.get(self.goals_key) or [])

    def close(self) -> None:
        pass


NAVIGATOR_TYPES = {
    'nav2_bt_navigator::NavigateToPoseNavigator': NavigateToPoseNavigator,
    'nav2_bt_navigator::NavigateThroughPosesNavigator': NavigateThroughPosesNavigator,
}


def default_tree(filename: str) -> str:
    return f"{get_package_share_directory('nav2_bt_navigator')}/behavior_trees/{filename}"


def client_node_name(node: Node, action_name: str) -> str:
    return f"{node.get_name()}_{action_name.replace('/', '_')}_rclcpp_node"
