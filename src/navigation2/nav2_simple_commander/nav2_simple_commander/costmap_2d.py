"""A costmap in Python, filled from an OccupancyGrid (upstream's `PyCostmap2D`).

The getters, cell/world conversions and index order follow nav2_costmap_2d's C++
Costmap2D, so code ported from C++ plugins reads the same.
"""

from __future__ import annotations

import numpy as np
from builtin_interfaces.msg import Time
from nav_msgs.msg import OccupancyGrid


class PyCostmap2D:
    """Costmap API over the cells of an OccupancyGrid (row-major, origin at cell 0, 0)."""

    def __init__(self, occupancy_map: OccupancyGrid) -> None:
        """Copy size, resolution, origin, frame, stamp and the cells (as uint8) of the map."""
        info = occupancy_map.info
        self.size_x = info.width
        self.size_y = info.height
        self.resolution = info.resolution
        self.origin_x = info.origin.position.x
        self.origin_y = info.origin.position.y
        self.global_frame_id = occupancy_map.header.frame_id
        self.costmap_timestamp = occupancy_map.header.stamp
        # The grid's int8 cells as costs 0-255: unknown (-1) reads 255, NO_INFORMATION.
        self.costmap = np.array(occupancy_map.data, dtype=np.int8).astype(np.uint8)

    def getSizeInCellsX(self) -> int:
        """Map width in cells."""
        return self.size_x

    def getSizeInCellsY(self) -> int:
        """Map height in cells."""
        return self.size_y

    def getSizeInMetersX(self) -> float:
        """Map width in metres, from the first cell's edge to the last cell's centre (as C++)."""
        return (self.size_x - 1 + 0.5) * self.resolution

    def getSizeInMetersY(self) -> float:
        """Map height in metres, measured as getSizeInMetersX."""
        return (self.size_y - 1 + 0.5) * self.resolution

    def getOriginX(self) -> float:
        """X of the map's origin [m]."""
        return self.origin_x

    def getOriginY(self) -> float:
        """Y of the map's origin [m]."""
        return self.origin_y

    def getResolution(self) -> float:
        """Resolution [m/cell]."""
        return self.resolution

    def getGlobalFrameID(self) -> str:
        """The map's frame id."""
        return self.global_frame_id

    def getCostmapTimestamp(self) -> Time:
        """The map's header stamp."""
        return self.costmap_timestamp

    def getCostXY(self, mx: int, my: int) -> np.uint8:
        """Cost of cell (mx, my)."""
        return self.costmap[self.getIndex(mx, my)]

    def getCostIdx(self, index: int) -> np.uint8:
        """Cost of the cell at a row-major index."""
        return self.costmap[index]

    def setCost(self, mx: int, my: int, cost: np.uint8) -> None:
        """Set the cost of cell (mx, my)."""
        self.costmap[self.getIndex(mx, my)] = cost

    def mapToWorld(self, mx: int, my: int) -> tuple[float, float]:
        """World coordinates [m] of the centre of cell (mx, my)."""
        return (self.origin_x + (mx + 0.5) * self.resolution,
                self.origin_y + (my + 0.5) * self.resolution)

    def worldToMapValidated(self, wx: float, wy: float
                            ) -> tuple[int, int] | tuple[None, None]:
        """Cell (mx, my) holding world point (wx, wy), or (None, None) off the map."""
        if wx < self.origin_x or wy < self.origin_y:
            return (None, None)
        mx = int((wx - self.origin_x) // self.resolution)
        my = int((wy - self.origin_y) // self.resolution)
        if mx < self.size_x and my < self.size_y:
            return (mx, my)
        return (None, None)

    def getIndex(self, mx: int, my: int) -> int:
        """Row-major index of cell (mx, my)."""
        return my * self.size_x + mx
