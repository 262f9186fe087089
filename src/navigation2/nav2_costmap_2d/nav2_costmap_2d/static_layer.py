"""StaticLayer: an OccupancyGrid (the map server's /map) as costs.

The values of the map are interpreted as upstream's interpretValue, from the costmap's own
parameters: `lethal_cost_threshold` (100), `unknown_cost_value` (255, the -1 of the grid read
as a byte), `trinary_costmap` (True) and `track_unknown_space` (False).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from nav2_costmap_2d.cost_values import FREE_SPACE, LETHAL_OBSTACLE, NO_INFORMATION
from nav2_costmap_2d.costmap_2d import Costmap2D
from nav2_costmap_2d.costmap_layer import CostmapLayer, ParameterError, read_parameter
from nav2_costmap_2d.footprint import transform_footprint


def interpret_values(data: np.ndarray, lethal_threshold: int, unknown_cost_value: int,
                     trinary_costmap: bool, track_unknown_space: bool) -> np.ndarray:
    """OccupancyGrid values (int8 -1..100, or their bytes) -> costs, as interpretValue."""
    value = np.asarray(data).astype(np.int16) & 0xFF  # C++ reads the int8 as unsigned char
    unknown = value == unknown_cost_value
    lethal = value >= lethal_threshold
    if trinary_costmap:
        costs = np.full(value.shape, FREE_SPACE, dtype=np.uint8)
    else:
        # scale = value / threshold, times LETHAL_OBSTACLE, truncated to a byte
        costs = (value.astype(np.float64) / lethal_threshold * LETHAL_OBSTACLE).astype(np.uint8)
    costs[lethal] = LETHAL_OBSTACLE
    costs[unknown] = NO_INFORMATION if track_unknown_space else FREE_SPACE
    return costs


class StaticLayer(CostmapLayer):
    """nav2_costmap_2d::StaticLayer (map from a topic, no tf: its frame is the costmap's)."""

    def __init__(self, name: str, layered_costmap: Any, params: Mapping[str, Any] | None = None,
                 node_params: Mapping[str, Any] | None = None) -> None:
        node = dict(node_params or {})
        self.track_unknown_space: bool = read_parameter(node, 'costmap', 'track_unknown_space',
                                                        False)
        self.use_maximum: bool = read_parameter(node, 'costmap', 'use_maximum', False)
        self.lethal_threshold: int = read_parameter(node, 'costmap', 'lethal_cost_threshold', 100)
        self.unknown_cost_value: int = read_parameter(node, 'costmap', 'unknown_cost_value', 255)
        self.trinary_costmap: bool = read_parameter(node, 'costmap', 'trinary_costmap', True)
        if not 1 <= self.lethal_threshold <= 255:
            raise ParameterError(f'lethal_cost_threshold: must be 1..255, got '
                                 f'{self.lethal_threshold}')
        default = NO_INFORMATION if self.track_unknown_space else FREE_SPACE
        super().__init__(name, layered_costmap, params, default_value=default)
        self.subscribe_to_updates: bool = self.parameter('subscribe_to_updates', False)
        self.map_subscribe_transient_local: bool = self.parameter(
            'map_subscribe_transient_local', True)
        self.transform_tolerance: float = self.parameter('transform_tolerance', 0.0)
        self.map_topic: str = self.parameter('map_topic', '')
        self.footprint_clearing_enabled: bool = self.parameter('footprint_clearing_enabled',
                                                               False)
        self.map_received = False
        self.map_grid: Costmap2D | None = None  # the map as received, for rolling windows
        self._footprint_cells: list[tuple[float, float]] = []

    def process_map(self, width: int, height: int, resolution: float, origin_x: float,
                    origin_y: float, data: np.ndarray | list[int]) -> None:
        """Take a map (OccupancyGrid info and data); resize a static master to it."""
        values = np.asarray(data)
        if values.size != width * height:
            raise ParameterError(f'map data: expected width*height = {width * height} values, '
                                 f'got {values.size}')
        costs = interpret_values(values, self.lethal_threshold, self.unknown_cost_value,
                                 self.trinary_costmap, self.track_unknown_space)
        costs = costs.reshape(height, width)
        self.map_grid = Costmap2D(width, height, resolution, origin_x, origin_y,
                                  self.default_value)
        self.map_grid.costmap[:] = costs
        master = self.layered_costmap.costmap
        if not self.layered_costmap.is_rolling():
            if (master.size_x, master.size_y) != (width, height) or not (
                    np.isclose(master.resolution, resolution) and
                    np.isclose(master.origin_x, origin_x) and
                    np.isclose(master.origin_y, origin_y)) or not self.layered_costmap.size_locked:
                self.layered_costmap.resize_map(width, height, resolution, origin_x, origin_y,
                                                True)
            self.match_size()
            self.costmap[:] = costs
        self.map_received = True
        self.current = True

    def reset(self) -> None:
        """Upstream keeps the map: a reset only asks for it to be written again."""
        self.current = False

    def update_bounds(self, robot_x: float, robot_y: float, robot_yaw: float) -> None:
        if self.footprint_clearing_enabled:
            self._footprint_cells = transform_footprint(robot_x, robot_y, robot_yaw,
                                                        self.layered_costmap.footprint)

    def update_costs(self, master: Costmap2D) -> None:
        if not self.enabled or not self.map_received:
            return
        if self.footprint_clearing_enabled and self._footprint_cells:
            self.set_convex_polygon_cost(self._footprint_cells, FREE_SPACE)
        if not self.layered_costmap.is_rolling():
            if self.use_maximum:
                self.update_with_max(master)
            else:
                self.update_with_true_overwrite(master)
        else:
            self._update_rolling(master)
        self.current = True  # upstream: written again after a reset (clear_entirely)

    def _update_rolling(self, master: Costmap2D) -> None:
        """Each master cell takes the map cell under its centre (same frame: no transform)."""
        grid = self.map_grid
        assert grid is not None
        xs = master.origin_x + (np.arange(master.size_x) + 0.5) * master.resolution
        ys = master.origin_y + (np.arange(master.size_y) + 0.5) * master.resolution
        mx, my, inside = grid.world_to_map_array(xs[None, :], ys[:, None])
        inside = np.broadcast_to(inside, master.costmap.shape)
        mx = np.broadcast_to(mx, master.costmap.shape)[inside]
        my = np.broadcast_to(my, master.costmap.shape)[inside]
        values = grid.costmap[my, mx]
        if self.use_maximum:
            old = master.costmap[inside]
            write = (values != NO_INFORMATION) & ((old == NO_INFORMATION) | (old < values))
            master.costmap[inside] = np.where(write, values, old)
        else:
            master.costmap[inside] = values
