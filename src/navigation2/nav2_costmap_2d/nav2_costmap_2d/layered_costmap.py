"""LayeredCostmap: the master grid and its plugins, rebuilt from them on every update.

Upstream tracks a bounding box of changed cells to save work in C++; here every update
rebuilds the whole master grid with vectorised layers, which gives the same grid.
"""

from __future__ import annotations

from collections.abc import Sequence

from nav2_costmap_2d.cost_values import FREE_SPACE, NO_INFORMATION
from nav2_costmap_2d.costmap_2d import Costmap2D
from nav2_costmap_2d.costmap_layer import Layer
from nav2_costmap_2d.footprint import Point, calculate_min_and_max_distances


class LayeredCostmap:
    """nav2_costmap_2d::LayeredCostmap: plugins combined in order into one master grid."""

    def __init__(self, global_frame: str = 'map', rolling_window: bool = False,
                 track_unknown: bool = False) -> None:
        self.global_frame = global_frame
        self.rolling_window = rolling_window
        self.track_unknown = track_unknown
        default = NO_INFORMATION if track_unknown else FREE_SPACE
        self.costmap = Costmap2D(default_value=default)
        self.plugins: list[Layer] = []
        self.size_locked = False
        self.initialized = False
        self.footprint: list[Point] = []
        self.inscribed_radius = 0.1
        self.circumscribed_radius = 1.0

    def is_rolling(self) -> bool:
        return self.rolling_window

    def add_plugin(self, plugin: Layer) -> None:
        self.plugins.append(plugin)

    def resize_map(self, size_x: int, size_y: int, resolution: float, origin_x: float,
                   origin_y: float, size_locked: bool = False) -> None:
        self.size_locked = size_locked
        self.costmap.resize_map(size_x, size_y, resolution, origin_x, origin_y)
        for plugin in self.plugins:
            plugin.match_size()

    def set_footprint(self, footprint: Sequence[Point]) -> None:
        self.footprint = list(footprint)
        self.inscribed_radius, self.circumscribed_radius = (
            calculate_min_and_max_distances(self.footprint))
        for plugin in self.plugins:
            plugin.on_footprint_changed()

    def is_out_of_bounds(self, robot_x: float, robot_y: float) -> bool:
        return self.costmap.world_to_map(robot_x, robot_y) is None

    def update_map(self, robot_x: float, robot_y: float, robot_yaw: float) -> None:
        """Re-centre a rolling window on the robot, then rebuild the master from the layers."""
        if self.rolling_window:
            self.costmap.update_origin(robot_x - self.costmap.size_in_meters_x / 2,
                                       robot_y - self.costmap.size_in_meters_y / 2)
        if not self.plugins:
            return
        for plugin in self.plugins:
            plugin.update_bounds(robot_x, robot_y, robot_yaw)
        self.costmap.reset_map()
        for plugin in self.plugins:
            plugin.update_costs(self.costmap)
        self.initialized = True

    def is_current(self) -> bool:
        return all(plugin.current or not plugin.enabled for plugin in self.plugins)
