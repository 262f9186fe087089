"""What a controller plugin is here, and how controller_server finds one by its type name.

Upstream loads `nav2_core::Controller` plugins with pluginlib; here a package registers its
controller class under the entry point group `nav2_core.controllers`, named by upstream's
type (`nav2_mppi_controller::MPPIController`), so controller_server imports no plugin
package. A plugin class is built as `cls(context)` and offers:

- `activate()`, `deactivate()`, `cleanup()`
- `set_plan(path)`: the global plan, an (N, 3) array of x, y, yaw in the plan's frame
- `compute_velocity_commands(pose, speed, goal_checker, plan_to_costmap) -> (vx, vy, wz)`:
  `pose` the robot in the costmap's global frame, `speed` (vx, vy, wz) from odometry,
  `plan_to_costmap` the plan frame's origin in the costmap frame; raises nav2_controller's
  exceptions (NoValidControl, ...)
- `cancel() -> bool` (True once the robot may be stopped), `reset()`,
  `set_speed_limit(speed_limit, percentage)`
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from importlib.metadata import entry_points
from typing import Any

CONTROLLER_GROUP = 'nav2_core.controllers'


@dataclass
class PluginContext:
    """What controller_server hands a controller plugin at configure."""

    node: Any  # the controller_server node (parameters, publishers, clock, logger)
    name: str  # the plugin's id, e.g. FollowPath: its parameters are `<name>.<key>`
    costmap_ros: Any  # the local costmap node (lock, costmap, footprint, frames)
    param: Callable[[str, Any], Any]  # declare `<name>.<key>` with a default, get its value


def plugin_key(plugin_type: str) -> str:
    """'nav2_mppi_controller/MPPIController' (pluginlib's other spelling) -> '...::...'."""
    return plugin_type.replace('/', '::')


def controller_types() -> dict[str, Any]:
    """Upstream type name -> entry point, of every controller installed."""
    return {ep.name: ep for ep in entry_points(group=CONTROLLER_GROUP)}


def load_controller(plugin_type: str) -> type | None:
    """The controller class registered under `plugin_type`, or None."""
    found = controller_types().get(plugin_key(plugin_type))
    return found.load() if found is not None else None
