"""Small real Nav2 servers for BasicNavigator's tests: Nav2's action and service names.

Run as a process next to a navigator script (`python nav2_stand_in_servers.py`). Each server
prints what it received (`<name> goal: ...`) so the test can check what the navigator sent;
the goal itself picks the behaviour, as no flags can reach a running server:

- navigate_to_pose / navigate_through_poses, by `behavior_tree`: '' succeeds after three
  feedbacks, 'abort' aborts with error_code 9999 after one, 'reject' is refused, 'slow'
  sends feedback every 0.1 s until canceled (aborting after 30 s).
- compute_path_to_pose, by `planner_id`: '' answers a straight 5-pose path, 'abort' aborts.
- the behaviours, follow_waypoints, follow_path, smooth_path, docking: succeed at once.
- two lifecycle managers' manage_nodes, map_server/load_map (a URL ending in `.yaml`
  succeeds), the costmaps' clear and get_costmap services.
- `--lifecycle`: lifecycle nodes amcl and bt_navigator instead; amcl answers an initial
  pose on amcl_pose, and bt_navigator turns active only after that.
"""

from __future__ import annotations

import argparse
import time
from typing import Any

import rclpy
from geometry_msgs.msg import PoseStamped, PoseWithCovarianceStamped
from lifecycle_msgs.msg import State
from nav2_msgs import action, srv
from nav2_msgs.msg import Costmap
from nav_msgs.msg import Path
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor
from rclpy.lifecycle import LifecycleNode, TransitionCallbackReturn
from rclpy.node import Node
from rclpy.qos import QoSDurabilityPolicy, QoSProfile

NAVIGATE_ERROR = 9999
SLOW_LIMIT = 30.0  # s a 'slow' navigation runs uncanceled before it aborts


def say(line: str) -> None:
    print(line, flush=True)


def xy(pose: PoseStamped) -> str:
    return f'{pose.pose.position.x:g} {pose.pose.position.y:g} in {pose.header.frame_id}'


def straight_path(start_x: float, goal_x: float, count: int = 5) -> Path:
    path = Path()
    path.header.frame_id = 'map'
    for i in range(count):
        pose = PoseStamped()
        pose.header.frame_id = 'map'
        pose.pose.position.x = start_x + (goal_x - start_x) * i / (count - 1)
        path.poses.append(pose)
    return path


class Nav2StandIn(Node):
    """The action and service servers a BasicNavigator script talks to."""

    def __init__(self) -> None:
        super().__init__('nav2_stand_in')
        group = ReentrantCallbackGroup()  # a slow navigation must not block a cancel
        for name, kind in (('navigate_to_pose', action.NavigateToPose),
                           ('navigate_through_poses', action.NavigateThroughPoses)):
            ActionServer(self, kind, name, self.navigating(kind), callback_group=group,
                         goal_callback=self.on_navigate_goal,
                         cancel_callback=lambda _goal: CancelResponse.ACCEPT)
        ActionServer(self, action.ComputePathToPose, 'compute_path_to_pose', self.on_plan,
                     callback_group=group)
        for name, kind in (('spin', action.Spin), ('backup', action.BackUp),
                           ('drive_on_heading', action.DriveOnHeading),
                           ('assisted_teleop', action.AssistedTeleop),
                           ('follow_waypoints', action.FollowWaypoints),
                           ('follow_path', action.FollowPath),
                           ('compute_path_through_poses', action.ComputePathThroughPoses),
                           ('smooth_path', action.SmoothPath),
                           ('dock_robot', action.DockRobot),
                           ('undock_robot', action.UndockRobot)):
            ActionServer(self, kind, name, self.succeeding(name, kind), callback_group=group)
        for manager in ('lifecycle_manager_localization', 'lifecycle_manager_navigation'):
            self.create_service(srv.ManageLifecycleNodes, f'{manager}/manage_nodes',
                                self.manager(manager))
        self.create_service(srv.LoadMap, 'map_server/load_map', self.on_load_map)
        for costmap in ('global_costmap', 'local_costmap'):
            self.create_service(srv.ClearEntireCostmap,
                                f'{costmap}/clear_entirely_{costmap}', self.cleared(costmap))
            self.create_service(srv.GetCostmap, f'{costmap}/get_costmap', self.costmap(costmap))
        self.create_service(srv.ClearCostmapAroundRobot,
                            'local_costmap/clear_costmap_around_robot',
                            self.cleared('around robot'))

    def on_navigate_goal(self, goal: Any) -> GoalResponse:
        poses = [goal.pose] if hasattr(goal, 'pose') else list(goal.poses)
        say(f"navigate goal: {' / '.join(xy(p) for p in poses)} bt='{goal.behavior_tree}'")
        return GoalResponse.REJECT if goal.behavior_tree == 'reject' else GoalResponse.ACCEPT

    def navigating(self, kind: Any) -> Any:
        def execute(handle: Any) -> Any:
            behaviour = handle.request.behavior_tree
            deadline = time.monotonic() + SLOW_LIMIT
            distance = 3.0
            while True:
                if handle.is_cancel_requested:
                    handle.canceled()
                    say('navigate canceled')
                    return kind.Result()
                handle.publish_feedback(kind.Feedback(distance_remaining=distance))
                say(f'navigate feedback: {distance:g}')
                if behaviour == 'abort':
                    handle.abort()
                    say('navigate aborted')
                    return kind.Result(error_code=NAVIGATE_ERROR, error_msg='stand-in abort')
                if behaviour == '' and distance <= 1.0:
                    handle.succeed()
                    say('navigate succeeded')
                    return kind.Result()
                if time.monotonic() > deadline:
                    handle.abort()
                    return kind.Result()
                if behaviour == '':
                    distance -= 1.0
                time.sleep(0.3 if behaviour == '' else 0.1)
        return execute

    def on_plan(self, handle: Any) -> Any:
        goal = handle.request
        say(f"compute_path_to_pose goal: {xy(goal.goal)} planner='{goal.planner_id}' "
            f'use_start={goal.use_start}')
        if goal.planner_id == 'abort':
            handle.abort()
            return action.ComputePathToPose.Result(error_code=208)
        handle.succeed()
        start = goal.start.pose.position.x if goal.use_start else 0.0
        return action.ComputePathToPose.Result(
            path=straight_path(start, goal.goal.pose.position.x))

    def succeeding(self, name: str, kind: Any) -> Any:
        def execute(handle: Any) -> Any:
            goal = handle.request
            fields = {field: getattr(goal, field) for field in goal.get_fields_and_field_types()}
            shown = {key: describe(value) for key, value in fields.items()}
            say(f'{name} goal: ' + ' '.join(f'{k}={v}' for k, v in shown.items()))
            handle.publish_feedback(kind.Feedback())
            handle.succeed()
            result = kind.Result()
            if hasattr(result, 'path') and hasattr(goal, 'path'):
                result.path = goal.path
                result.path.header.frame_id = 'smoothed'
            elif hasattr(result, 'path'):
                result.path = straight_path(0.0, goal.goals[-1].pose.position.x, 3)
            return result
        return execute

    def manager(self, name: str) -> Any:
        def on_manage(request: Any, response: Any) -> Any:
            say(f'{name} command: {request.command}')
            response.success = True
            return response
        return on_manage

    def on_load_map(self, request: Any, response: Any) -> Any:
        say(f'load_map: {request.map_url}')
        response.result = (srv.LoadMap.Response.RESULT_SUCCESS if request.map_url.endswith('.yaml')
                           else srv.LoadMap.Response.RESULT_MAP_DOES_NOT_EXIST)
        return response

    def cleared(self, name: str) -> Any:
        def on_clear(request: Any, response: Any) -> Any:
            distance = getattr(request, 'reset_distance', None)
            say(f'clear {name}' + ('' if distance is None else f' reset_distance={distance:g}'))
            return response
        return on_clear

    def costmap(self, name: str) -> Any:
        def on_get(request: Any, response: Any) -> Any:
            response.map = Costmap()
            response.map.header.frame_id = 'map' if name == 'global_costmap' else 'odom'
            response.map.metadata.size_x, response.map.metadata.size_y = 3, 2
            response.map.data = [0, 0, 254, 0, 100, 0]
            return response
        return on_get


def describe(value: Any) -> str:
    if isinstance(value, PoseStamped):
        return xy(value)
    if hasattr(value, 'sec') and hasattr(value, 'nanosec'):
        return f'{value.sec + value.nanosec / 1e9:g}s'
    if hasattr(value, 'x') and hasattr(value, 'y') and hasattr(value, 'z'):
        return f'{value.x:g}'
    if isinstance(value, Path):
        return f'path[{len(value.poses)}]'
    if isinstance(value, float):
        return f'{value:g}'
    if isinstance(value, list):
        return f'[{len(value)}]'
    return repr(value)


class StandInLifecycle(LifecycleNode):
    """A managed node (amcl or bt_navigator) with real lifecycle services."""

    def on_configure(self, state: State) -> TransitionCallbackReturn:
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        say(f'{self.get_name()} active')
        return super().on_activate(state)


def run_lifecycle() -> None:
    amcl = StandInLifecycle('amcl')
    navigator = StandInLifecycle('bt_navigator')
    latched = QoSProfile(depth=1, durability=QoSDurabilityPolicy.TRANSIENT_LOCAL)
    amcl_pose = amcl.create_publisher(PoseWithCovarianceStamped, 'amcl_pose', latched)

    pending: list[Any] = []
    activated: list[bool] = []

    def activate_navigator() -> None:
        pending.pop().cancel()
        navigator.trigger_activate()

    def on_initial_pose(msg: PoseWithCovarianceStamped) -> None:
        say(f'initialpose: {msg.pose.pose.position.x:g} {msg.pose.pose.position.y:g} '
            f'in {msg.header.frame_id}')
        amcl_pose.publish(msg)
        if not pending and not activated:  # bt_navigator turns active a second later
            pending.append(navigator.create_timer(1.0, activate_navigator))
            activated.append(True)

    amcl.create_subscription(PoseWithCovarianceStamped, 'initialpose', on_initial_pose, 10)
    for node in (amcl, navigator):
        node.trigger_configure()
    amcl.trigger_activate()
    spin_all([amcl, navigator])


def spin_all(nodes: list[Node]) -> None:
    executor = MultiThreadedExecutor(num_threads=4)
    for node in nodes:
        executor.add_node(node)
    say('stand-in servers ready')
    try:
        executor.spin()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument('--lifecycle', action='store_true')
    args = parser.parse_args()
    rclpy.init()
    if args.lifecycle:
        run_lifecycle()
    else:
        spin_all([Nav2StandIn()])
    rclpy.try_shutdown()


if __name__ == '__main__':
    main()
