"""Cost of a robot footprint on a PyCostmap2D (upstream's `FootprintCollisionChecker`).

A footprint costs the highest cell cost along its edges; a vertex off the map, or a
lethal cell on an edge, costs LETHAL_OBSTACLE at once.
"""

from __future__ import annotations

from math import cos, sin

import numpy as np
from geometry_msgs.msg import Point32, Polygon

from nav2_simple_commander.costmap_2d import PyCostmap2D
from nav2_simple_commander.line_iterator import LineIterator

# nav2_costmap_2d's cost values
NO_INFORMATION = 255
LETHAL_OBSTACLE = 254
INSCRIBED_INFLATED_OBSTACLE = 253
MAX_NON_OBSTACLE = 252
FREE_SPACE = 0

_NO_COSTMAP = 'Costmap not specified, use setCostmap to specify the costmap first'


class FootprintCollisionChecker:
    """Footprint, line and point costs on the costmap given to setCostmap."""

    def __init__(self) -> None:
        """Start without a costmap: the cost queries raise ValueError until setCostmap."""
        self.costmap_: PyCostmap2D | None = None

    def footprintCost(self, footprint: Polygon) -> float:
        """Highest cost along the closed polygon's edges (map frame, metres)."""
        cells = []
        for point in footprint.points:
            mx, my = self.worldToMapValidated(point.x, point.y)
            if mx is None or my is None:
                return LETHAL_OBSTACLE
            cells.append((mx, my))
        if not cells:
            return 0.0
        cost = 0.0
        # Each edge, then the one closing the polygon from the last vertex to the first.
        for (x0, y0), (x1, y1) in zip(cells, cells[1:] + cells[:1], strict=True):
            cost = max(float(self.lineCost(x0, x1, y0, y1)), cost)
            if cost == LETHAL_OBSTACLE:
                break
        return cost

    def lineCost(self, x0: int, x1: int, y0: int, y1: int, step_size: float = 0.5) -> float:
        """Highest cell cost on the line from map cell (x0, y0) to (x1, y1)."""
        if x0 == x1 and y0 == y1:
            # Two vertices in one cell: that cell is the whole line (LineIterator refuses it).
            return self.pointCost(int(x0), int(y0))
        line_cost = 0.0
        line = LineIterator(x0, y0, x1, y1, step_size)
        while line.isValid():
            point_cost = self.pointCost(int(line.getX()), int(line.getY()))
            if point_cost == LETHAL_OBSTACLE:
                return point_cost
            line_cost = max(line_cost, point_cost)
            line.advance()
        return line_cost

    def worldToMapValidated(self, wx: float, wy: float
                            ) -> tuple[int, int] | tuple[None, None]:
        """Map cell of a world point, (None, None) off the map."""
        if self.costmap_ is None:
            raise ValueError(_NO_COSTMAP)
        return self.costmap_.worldToMapValidated(wx, wy)

    def pointCost(self, x: int, y: int) -> np.uint8:
        """Cost of map cell (x, y)."""
        if self.costmap_ is None:
            raise ValueError(_NO_COSTMAP)
        return self.costmap_.getCostXY(x, y)

    def setCostmap(self, costmap: PyCostmap2D) -> None:
        """Use this costmap for the cost queries."""
        self.costmap_ = costmap

    def footprintCostAtPose(self, x: float, y: float, theta: float,
                            footprint: Polygon) -> float:
        """Cost of the robot-frame footprint placed at (x, y) with heading theta [rad]."""
        cos_th, sin_th = cos(theta), sin(theta)
        placed = Polygon()
        for point in footprint.points:
            placed.points.append(Point32(x=x + point.x * cos_th - point.y * sin_th,
                                         y=y + point.x * sin_th + point.y * cos_th))
        return self.footprintCost(placed)
