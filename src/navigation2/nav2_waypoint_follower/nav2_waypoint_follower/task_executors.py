"""The waypoint task executors (nav2_core::WaypointTaskExecutor plugins), by upstream name.

Only WaitAtWaypoint is built: PhotoAtWaypoint needs cv_bridge and image saving, and
InputAtWaypoint a user input topic; naming either gives one line saying so.
"""

from __future__ import annotations

import time
from typing import Any

from nav2_util.parameters import declare_checked


class WaitAtWaypoint:
    """nav2_waypoint_follower::WaitAtWaypoint: sleep waypoint_pause_duration ms there."""

    def __init__(self) -> None:
        self.waypoint_pause_duration = 0
        self.enabled = True
        self.logger: Any = None

    def initialize(self, node: Any, name: str) -> None:
        self.logger = node.get_logger()
        self.waypoint_pause_duration = _declared(node, f'{name}.waypoint_pause_duration', 0)
        self.enabled = _declared(node, f'{name}.enabled', True)
        if self.waypoint_pause_duration < 0:
            self.logger.error(f"Parameter '{name}.waypoint_pause_duration' must be >= 0 ms, "
                              f'got {self.waypoint_pause_duration}: using 0')
            self.waypoint_pause_duration = 0
        if self.waypoint_pause_duration == 0:
            self.enabled = False
            self.logger.info(
                'Waypoint pause duration is set to zero, disabling task executor plugin.')
        elif not self.enabled:
            self.logger.info('Waypoint task executor plugin is disabled.')

    def process_at_waypoint(self, pose: Any, index: int) -> bool:
        if not self.enabled:
            return True
        self.logger.info(f"Arrived at {index}'th waypoint, sleeping for "
                         f'{self.waypoint_pause_duration} milliseconds')
        time.sleep(self.waypoint_pause_duration / 1000.0)
        return True


class NotBuilt(Exception):
    pass


NOT_BUILT = {
    'nav2_waypoint_follower::PhotoAtWaypoint': 'it needs cv_bridge and an image writer',
    'nav2_waypoint_follower::InputAtWaypoint': 'it is not part of this workspace yet',
}
TASK_EXECUTORS = {'nav2_waypoint_follower::WaitAtWaypoint': WaitAtWaypoint}


def create_task_executor(plugin_type: str) -> WaitAtWaypoint:
    key = plugin_type.replace('/', '::')
    if key in NOT_BUILT:
        raise NotBuilt(f'{key} is not built in this workspace: {NOT_BUILT[key]}')
    cls = TASK_EXECUTORS.get(key)
    if cls is None:
        raise NotBuilt(
            f'According to the loaded plugin descriptions the class {plugin_type} with base '
            'class type nav2_core::WaypointTaskExecutor does not exist. Declared types are  '
            + '  '.join(sorted(TASK_EXECUTORS)))
    return cls()


def _declared(node: Any, name: str, default: Any) -> Any:
    if node.has_parameter(name):
        return node.get_parameter(name).value
    return declare_checked(node, name, default)
