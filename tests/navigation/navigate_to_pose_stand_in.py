"""A scripted `navigate_to_pose` server for waypoint_follower's tests (until bt_navigator
runs here): real rclpy action server, Nav2's name and type; what it does with a goal is
written in the goal's pose z (a waypoint's height is of no use to a ground robot):

- z = 0: feedback, then SUCCEEDED after 0.2 s;
- z = -1: ABORTED with error_code 105 after 0.1 s;
- z = -2: the goal is rejected;
- z = 1: feedback every 0.1 s until canceled (ABORTED after 30 s).

Each goal is printed as `navigate_to_pose goal: <x> <y>` and its end as
`navigate_to_pose <succeeded|aborted|canceled>: <x> <y>`.
"""

from __future__ import annotations

import sys
import time
from typing import Any

from nav2_msgs.action import NavigateToPose
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node

ABORT_CODE = 105
SLOW_LIMIT = 30.0


def say(line: str) -> None:
    print(line, flush=True)


def where(goal: Any) -> str:
    return f'{goal.pose.pose.position.x:g} {goal.pose.pose.position.y:g}'


class NavigateStandIn(Node):
    def __init__(self) -> None:
        super().__init__('bt_navigator')
        self.server = ActionServer(
            self, NavigateToPose, 'navigate_to_pose', self.on_execute,
            goal_callback=self.on_goal, cancel_callback=lambda _goal: CancelResponse.ACCEPT,
            callback_group=ReentrantCallbackGroup())

    def on_goal(self, goal: Any) -> GoalResponse:
        say(f'navigate_to_pose goal: {where(goal)}')
        return GoalResponse.REJECT if goal.pose.pose.position.z == -2.0 else \
            GoalResponse.ACCEPT

    def on_execute(self, handle: Any) -> Any:
        goal = handle.request
        z = goal.pose.pose.position.z
        handle.publish_feedback(NavigateToPose.Feedback(current_pose=goal.pose))
        deadline = time.monotonic() + (SLOW_LIMIT if z == 1.0 else 0.2 if z == 0.0 else 0.1)
        while time.monotonic() < deadline:
            if handle.is_cancel_requested:
                handle.canceled()
                say(f'navigate_to_pose canceled: {where(goal)}')
                return NavigateToPose.Result()
            time.sleep(0.02)
        if z == 0.0:
            handle.succeed()
            say(f'navigate_to_pose succeeded: {where(goal)}')
            return NavigateToPose.Result()
        handle.abort()
        say(f'navigate_to_pose aborted: {where(goal)}')
        return NavigateToPose.Result(error_code=ABORT_CODE, error_msg='stand-in abort')


def main() -> int:
    with ros_session(sys.argv) as stop:
        node = NavigateStandIn()
        say('navigate_to_pose ready')
        spin_until_stopped(node, stop, MultiThreadedExecutor(num_threads=4))
    return 0


if __name__ == '__main__':
    sys.exit(main())
