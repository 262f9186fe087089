"""Real rclpy servers under Nav2's names for the servers bt_navigator's default trees call and
this test stack does not run: follow_path, spin, backup, wait, drive_on_heading,
smooth_path and local_costmap/clear_entirely_local_costmap.

Run as a process (`python bt_navigator_stand_ins.py`); each server prints what it got.
follow_path sends feedback every 0.1 s and succeeds after FOLLOW_TIME, except for a path
ending at x >= LONG_X (m), which it follows until canceled or replaced (then it ends, as
a preempted controller goal does) or for at most LONG_LIMIT. The behaviours succeed at once.
"""

from __future__ import annotations

import time
from typing import Any

import rclpy
from nav2_msgs import action, srv
from rclpy.action import ActionServer, CancelResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor
from rclpy.node import Node

FOLLOW_TIME = 0.5
LONG_X = 4.0
LONG_LIMIT = 30.0


def say(line: str) -> None:
    print(line, flush=True)


class StandIns(Node):
    def __init__(self) -> None:
        super().__init__('bt_navigator_stand_ins')
        group = ReentrantCallbackGroup()
        self.latest_follow: Any = None
        ActionServer(self, action.FollowPath, 'follow_path', self.on_follow,
                     handle_accepted_callback=self.on_follow_accepted,
                     cancel_callback=lambda _handle: CancelResponse.ACCEPT,
                     callback_group=group)
        for name, kind in (('spin', action.Spin), ('backup', action.BackUp),
                           ('wait', action.Wait), ('drive_on_heading', action.DriveOnHeading),
                           ('smooth_path', action.SmoothPath)):
            ActionServer(self, kind, name, self.succeeding(name, kind), callback_group=group)
        self.create_service(srv.ClearEntireCostmap,
                            'local_costmap/clear_entirely_local_costmap', self.on_clear)

    def on_follow_accepted(self, handle: Any) -> None:
        self.latest_follow = handle
        handle.execute()

    def on_follow(self, handle: Any) -> Any:
        path = handle.request.path
        end = path.poses[-1].pose.position if path.poses else None
        say(f'follow_path goal: {len(path.poses)} poses to '
            f'({end.x if end else 0:.2f}, {end.y if end else 0:.2f}) '
            f"controller='{handle.request.controller_id}'")
        long = end is not None and end.x >= LONG_X
        started = time.monotonic()
        while True:
            if handle.is_cancel_requested:
                handle.canceled()
                say('follow_path canceled')
                return action.FollowPath.Result()
            if handle is not self.latest_follow:
                handle.abort()  # preempted by a newer path
                return action.FollowPath.Result()
            elapsed = time.monotonic() - started
            if (not long and elapsed >= FOLLOW_TIME) or elapsed >= LONG_LIMIT:
                handle.succeed()
                say('follow_path succeeded')
                return action.FollowPath.Result()
            handle.publish_feedback(action.FollowPath.Feedback(distance_to_goal=1.0, speed=0.2))
            time.sleep(0.1)

    def succeeding(self, name: str, kind: Any) -> Any:
        def execute(handle: Any) -> Any:
            say(f'{name} goal')
            handle.succeed()
            return kind.Result()
        return execute

    def on_clear(self, _request: Any, response: Any) -> Any:
        say('clear local costmap')
        return response


def main() -> None:
    rclpy.init()
    node = StandIns()
    executor = MultiThreadedExecutor(num_threads=4)
    executor.add_node(node)
    say('stand-ins ready')
    try:
        executor.spin()
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    rclpy.try_shutdown()


if __name__ == '__main__':
    main()
