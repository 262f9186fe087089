"""Layer and CostmapLayer: what every plugin of a LayeredCostmap shares.

A layer reads its parameters from the mapping a Nav2 params file gives under its name
(`inflation_layer: {inflation_radius: 0.55, ...}`), with Nav2's defaults. Layers with a grid of
their own (static, obstacle) combine it into the master grid as upstream's updateWith* do,
here on whole numpy arrays.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from nav2_costmap_2d.cost_values import INSCRIBED_INFLATED_OBSTACLE, NO_INFORMATION
from nav2_costmap_2d.costmap_2d import Costmap2D


class ParameterError(ValueError):
    """A layer parameter of the wrong type or out of range; one line naming it."""


def read_parameter(params: Mapping[str, Any], prefix: str, name: str, default: Any) -> Any:
    """params[name] checked against the type of Nav2's default (an int may stand for a double)."""
    if name not in params:
        return default
    value = params[name]
    expected = type(default)
    if expected is float and isinstance(value, int) and not isinstance(value, bool):
        return float(value)
    if (expected is not bool and isinstance(value, bool)) or not isinstance(value, expected):
        raise ParameterError(f'{prefix}.{name}: expected {expected.__name__}, got {value!r}')
    return value


class Layer:
    """A plugin of the layered costmap (nav2_costmap_2d::Layer)."""

    def __init__(self, name: str, layered_costmap: Any,
                 params: Mapping[str, Any] | None = None) -> None:
        self.name = name
        self.layered_costmap = layered_costmap
        self.params = dict(params or {})
        self.enabled: bool = self.parameter('enabled', True)
        self.current = True

    def parameter(self, name: str, default: Any) -> Any:
        return read_parameter(self.params, self.name, name, default)

    def match_size(self) -> None:
        """The master grid changed size or resolution."""

    def on_footprint_changed(self) -> None:
        """The robot footprint (and so the inscribed radius) changed."""

    def update_bounds(self, robot_x: float, robot_y: float, robot_yaw: float) -> None:
        """Take in new data before the master grid is rebuilt."""

    def update_costs(self, master: Costmap2D) -> None:
        """Write this layer into the master grid."""

    def reset(self) -> None:
        """Forget what the layer has gathered (the clear_* services)."""

    def is_clearable(self) -> bool:
        return False


class CostmapLayer(Layer, Costmap2D):
    """A layer with a grid of its own, the size of the master grid."""

    def __init__(self, name: str, layered_costmap: Any,
                 params: Mapping[str, Any] | None = None, default_value: int = 0) -> None:
        Layer.__init__(self, name, layered_costmap, params)
        Costmap2D.__init__(self, default_value=default_value)
        self.match_size()

    def match_size(self) -> None:
        master = self.layered_costmap.costmap
        self.resize_map(master.size_x, master.size_y, master.resolution, master.origin_x,
                        master.origin_y)

    def reset(self) -> None:
        self.reset_map()
        self.current = False

    def clear_area(self, start_x: int, start_y: int, end_x: int, end_y: int,
                   invert: bool) -> None:
        """Cells strictly inside (invert=False) or outside (invert=True) the window -> unknown."""
        xs = np.arange(self.size_x)
        ys = np.arange(self.size_y)
        inside = (((xs > start_x) & (xs < end_x))[None, :]
                  & ((ys > start_y) & (ys < end_y))[:, None])
        self.current = False
        self.costmap[inside != invert] = NO_INFORMATION

    # --- upstream's combination methods, on the whole grid ------------------------------
    def update_with_max(self, master: Costmap2D) -> None:
        """Known cells raise the master; the master's unknown cells take the layer's value."""
        if not self.enabled:
            return
        layer, grid = self.costmap, master.costmap
        write = (layer != NO_INFORMATION) & ((grid == NO_INFORMATION) | (grid < layer))
        grid[write] = layer[write]

    def update_with_max_without_unknown_overwrite(self, master: Costmap2D) -> None:
        if not self.enabled:
            return
        layer, grid = self.costmap, master.costmap
        write = (layer != NO_INFORMATION) & (grid != NO_INFORMATION) & (grid < layer)
        grid[write] = layer[write]

    def update_with_true_overwrite(self, master: Costmap2D) -> None:
        if self.enabled:
            master.costmap[:] = self.costmap

    def update_with_overwrite(self, master: Costmap2D) -> None:
        if not self.enabled:
            return
        known = self.costmap != NO_INFORMATION
        master.costmap[known] = self.costmap[known]

    def update_with_addition(self, master: Costmap2D) -> None:
        if not self.enabled:
            return
        layer, grid = self.costmap, master.costmap
        known = layer != NO_INFORMATION
        total = np.minimum(grid.astype(np.int32) + layer, INSCRIBED_INFLATED_OBSTACLE - 1)
        result = np.where(grid == NO_INFORMATION, layer, total)
        grid[known] = result[known]
