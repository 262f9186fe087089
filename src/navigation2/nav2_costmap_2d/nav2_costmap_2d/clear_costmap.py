"""What the clear_* services of a costmap do (ClearCostmapService)."""

from __future__ import annotations

from nav2_costmap_2d.costmap_layer import CostmapLayer
from nav2_costmap_2d.layered_costmap import LayeredCostmap


def clear_layer_region(layer: CostmapLayer, x: float, y: float, reset_distance: float,
                       invert: bool) -> None:
    """A reset_distance square centred on (x, y): its inside (or, inverted, its outside)."""
    start_x, start_y = x - reset_distance / 2, y - reset_distance / 2
    x0, y0 = layer.world_to_map_enforce_bounds(start_x, start_y)
    x1, y1 = layer.world_to_map_enforce_bounds(start_x + reset_distance,
                                               start_y + reset_distance)
    layer.clear_area(x0, y0, x1, y1, invert)


def clear_region(layered: LayeredCostmap, x: float, y: float, reset_distance: float,
                 invert: bool) -> None:
    """clear_around_<costmap> (invert=False) and clear_except_<costmap> (invert=True)."""
    for layer in layered.plugins:
        if layer.is_clearable() and isinstance(layer, CostmapLayer):
            clear_layer_region(layer, x, y, reset_distance, invert)


def clear_entirely(layered: LayeredCostmap) -> None:
    """clear_entirely_<costmap>: the master grid and every layer reset."""
    layered.costmap.reset_map()
    for layer in layered.plugins:
        layer.reset()
