"""Nav2's leaves that work on the blackboard and topics only: RemovePassedGoals,
TruncatePath, the plugin selectors, and the GoalUpdater decorator."""

from __future__ import annotations

import math
from typing import Any

from nav2_behavior_tree import robot
from nav2_behavior_tree.core import (
    ActionNode,
    DecoratorNode,
    InputPort,
    NodeStatus,
    OutputPort,
    is_active,
    ports,
    to_float,
)

S, F = NodeStatus.SUCCESS, NodeStatus.FAILURE


class RemovePassedGoals(ActionNode):
    PORTS = ports(input_goals=InputPort(None, None, 'Original goals to remove viapoints from'),
             output_goals=OutputPort('Goals with passed viapoints removed'),
             radius=InputPort(to_float, 0.5, 'radius to goal for it to be considered for '
                                 'removal'),
             global_frame=InputPort(str, None, 'Global frame'),
             robot_base_frame=InputPort(str, None, 'Robot base frame'))

    def tick(self) -> NodeStatus:
        goals = list(self.get_input('input_goals') or [])
        if not goals:
            self.set_output('output_goals', goals)
            return S
        pose = robot.current_pose(self.blackboard, self.get_input('global_frame'),
                                  self.get_input('robot_base_frame'))
        if pose is None:
            return F
        radius = self.get_input('radius')
        while len(goals) > 1 and math.dist(robot.xy_of(goals[0]), pose[:2]) <= radius:
            goals.pop(0)
        self.set_output('output_goals', goals)
        return S


class TruncatePath(ActionNode):
    PORTS = ports(input_path=InputPort(None, None, 'Original Path'),
             output_path=OutputPort('Path truncated to a certain distance'),
             distance=InputPort(to_float, 1.0, 'distance'))

    def tick(self) -> NodeStatus:
        path = self.get_input('input_path')
        if path is None:
            return F
        if not path.poses:
            self.set_output('output_path', path)
            return S
        poses = list(path.poses)
        final = robot.xy_of(poses[-1])
        limit = self.get_input('distance')
        while len(poses) > 2 and math.dist(robot.xy_of(poses[-1]), final) < limit:
            poses.pop()
        truncated = type(path)(header=path.header, poses=poses)
        self.set_output('output_path', truncated)
        return S


class _Selector(ActionNode):
    """Publishes on its output the last name heard on `topic_name` (latched), else the
    default: how a tree switches planners, controllers or checkers at run time."""

    KIND = ''
    TOPIC = ''

    @classmethod
    def ports(cls) -> dict[str, Any]:
        return {f'default_{cls.KIND}': InputPort(str, '', f'the default {cls.KIND} to use'),
                'topic_name': InputPort(str, cls.TOPIC, f'the input topic name to select the '
                                        f'{cls.KIND}'),
                f'selected_{cls.KIND}': OutputPort(f'Selected {cls.KIND} by subscription')}

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.last_selected = ''
        self.subscription = None
        node = self.blackboard.get('node')
        if node is not None:
            from rclpy.qos import DurabilityPolicy, QoSProfile
            from std_msgs.msg import String
            latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
            self.subscription = node.create_subscription(
                String, self.get_input('topic_name'), self.on_selection, latched,
                callback_group=self.blackboard.get('callback_group'))

    def on_selection(self, msg: Any) -> None:
        self.last_selected = msg.data

    def tick(self) -> NodeStatus:
        selected = self.last_selected or self.get_input(f'default_{self.KIND}')
        self.set_output(f'selected_{self.KIND}', selected)
        return S

    def close(self) -> None:
        node = self.blackboard.get('node')
        if node is not None and self.subscription is not None:
            node.destroy_subscription(self.subscription)
            self.subscription = None


class ControllerSelector(_Selector):
    KIND, TOPIC = 'controller', 'controller_selector'


class PlannerSelector(_Selector):
    KIND, TOPIC = 'planner', 'planner_selector'


class GoalCheckerSelector(_Selector):
    KIND, TOPIC = 'goal_checker', 'goal_checker_selector'


class SmootherSelector(_Selector):
    KIND, TOPIC = 'smoother', 'smoother_selector'


class ProgressCheckerSelector(_Selector):
    KIND, TOPIC = 'progress_checker', 'progress_checker_selector'


class GoalUpdater(DecoratorNode):
    """Replaces input_goal with a newer pose heard on `goal_update` before ticking."""

    PORTS = ports(input_goal=InputPort(None, None, 'Original Goal'),
             output_goal=OutputPort('Received Goal by subscription'))

    def __init__(self, *args) -> None:
        super().__init__(*args)
        self.last_goal = None
        self.subscription = None
        node = self.blackboard.get('node')
        if node is not None:
            from geometry_msgs.msg import PoseStamped
            topic = self.blackboard.get('goal_updater_topic', 'goal_update')
            self.subscription = node.create_subscription(
                PoseStamped, topic, self.on_goal, 10,
                callback_group=self.blackboard.get('callback_group'))

    def on_goal(self, msg: Any) -> None:
        self.last_goal = msg

    def tick(self) -> NodeStatus:
        goal = self.get_input('input_goal')
        if self.last_goal is not None and (goal is None or stamp(self.last_goal) > stamp(goal)):
            goal = self.last_goal
        self.set_output('output_goal', goal)
        if not is_active(self.status):
            self.status = NodeStatus.RUNNING
        return self.child.execute_tick()

    def close(self) -> None:
        node = self.blackboard.get('node')
        if node is not None and self.subscription is not None:
            node.destroy_subscription(self.subscription)
            self.subscription = None


def stamp(pose: Any) -> float:
    return pose.header.stamp.sec + pose.header.stamp.nanosec * 1e-9


ACTION_HELPERS = {cls.__name__: cls for cls in (
    RemovePassedGoals, TruncatePath, ControllerSelector, PlannerSelector, GoalCheckerSelector,
    SmootherSelector, ProgressCheckerSelector)}
HELPER_DECORATORS = {'GoalUpdater': GoalUpdater}
