"""nav2_simple_commander's pure helpers: PyCostmap2D, LineIterator, FootprintCollisionChecker.

Plain functions on messages built in the test: no ROS graph is involved.
"""

from __future__ import annotations

import math

import pytest
from geometry_msgs.msg import Point32, Polygon
from nav2_simple_commander.costmap_2d import PyCostmap2D
from nav2_simple_commander.footprint_collision_checker import (
    LETHAL_OBSTACLE,
    NO_INFORMATION,
    FootprintCollisionChecker,
)
from nav2_simple_commander.line_iterator import LineIterator
from nav_msgs.msg import OccupancyGrid


def grid(width: int, height: int, resolution: float = 1.0, origin: tuple[float, float] = (0, 0),
         cells: dict[tuple[int, int], int] | None = None) -> OccupancyGrid:
    msg = OccupancyGrid()
    msg.header.frame_id = 'map'
    msg.header.stamp.sec = 42
    msg.info.width, msg.info.height, msg.info.resolution = width, height, resolution
    msg.info.origin.position.x, msg.info.origin.position.y = float(origin[0]), float(origin[1])
    data = [0] * (width * height)
    for (mx, my), value in (cells or {}).items():
        data[my * width + mx] = value
    msg.data = data
    return msg


def polygon(*points: tuple[float, float]) -> Polygon:
    return Polygon(points=[Point32(x=float(x), y=float(y)) for x, y in points])


def walk(line: LineIterator, limit: int = 100) -> list[tuple[float, float]]:
    points = []
    while line.isValid() and len(points) < limit:
        points.append((line.getX(), line.getY()))
        line.advance()
    return points


# --- PyCostmap2D ---------------------------------------------------------------------------

def test_costmap_takes_size_origin_frame_and_stamp_from_the_grid():
    costmap = PyCostmap2D(grid(4, 3, 0.5, (-1.0, 2.0)))
    assert (costmap.getSizeInCellsX(), costmap.getSizeInCellsY()) == (4, 3)
    # Costmap2D's sizes in metres run from the first cell's edge to the last cell's centre.
    assert costmap.getSizeInMetersX() == pytest.approx(1.75)
    assert costmap.getSizeInMetersY() == pytest.approx(1.25)
    assert (costmap.getOriginX(), costmap.getOriginY(), costmap.getResolution()) == (-1, 2, 0.5)
    assert costmap.getGlobalFrameID() == 'map'
    assert costmap.getCostmapTimestamp().sec == 42


def test_costmap_cells_are_row_major_and_unknown_reads_no_information():
    costmap = PyCostmap2D(grid(4, 3, cells={(3, 0): 100, (1, 2): -1}))
    assert costmap.getIndex(3, 0) == 3 and costmap.getIndex(1, 2) == 9
    assert costmap.getCostXY(3, 0) == 100 and costmap.getCostIdx(3) == 100
    assert costmap.getCostXY(1, 2) == NO_INFORMATION
    costmap.setCost(2, 1, 254)
    assert costmap.getCostIdx(6) == 254 and costmap.costmap.dtype.name == 'uint8'


def test_costmap_converts_between_cells_and_world():
    costmap = PyCostmap2D(grid(4, 3, 0.5, (-1.0, 2.0)))
    assert costmap.mapToWorld(0, 0) == pytest.approx((-0.75, 2.25))  # the cell's centre
    assert costmap.mapToWorld(3, 2) == pytest.approx((0.75, 3.25))
    assert costmap.worldToMapValidated(0.9, 3.4) == (3, 2)
    assert costmap.worldToMapValidated(-1.0, 2.0) == (0, 0)
    for outside in ((-1.01, 2.5), (0.0, 1.99), (1.0, 2.5), (0.0, 3.5)):
        assert costmap.worldToMapValidated(*outside) == (None, None), outside


# --- LineIterator ---------------------------------------------------------------------------

def test_line_iterator_steps_along_x_backwards_on_a_steep_line():
    assert walk(LineIterator(2, 1, -2, -7)) == [(2, 1), (1, -1), (0, -3), (-1, -5), (-2, -7)]


def test_line_iterator_steps_along_y_on_a_vertical_line_and_clamps_the_last_step():
    assert walk(LineIterator(3, 4, 3, 1.5, 1)) == [(3, 4), (3, 3), (3, 2), (3, 1.5)]
    assert walk(LineIterator(0, 0, 2, 1, 0.5)) == [(0, 0), (0.5, 0.25), (1, 0.5),
                                                  (1.5, 0.75), (2, 1)]


def test_line_iterator_keeps_its_end_points_and_length():
    line = LineIterator(1, 2, 4, 6)
    assert (line.getX0(), line.getY0(), line.getX1(), line.getY1()) == (1, 2, 4, 6)
    assert line.get_line_length() == 5.0
    assert line.clamp(7, 0, 5) == 5 and line.clamp(-1, 0, 5) == 0 and line.clamp(3, 0, 5) == 3


@pytest.mark.parametrize('args, error, message', [
    ((0, 0, '1', 1), TypeError, 'x1 must be a number (int or float)'),
    ((0, True, 1, 1), TypeError, 'y0 must be a number (int or float)'),
    ((0, 0, 1, 1, None), TypeError, 'step_size must be a number (int or float)'),
    ((0, 0, 1, 1, 0), ValueError, 'step_size must be a positive number'),
    ((2.5, 1, 2.5, 1), ValueError, 'Line has zero length'),
])
def test_line_iterator_refuses_bad_input_naming_it(args, error, message):
    with pytest.raises(error) as raised:
        LineIterator(*args)
    assert str(raised.value).startswith(message)


# --- FootprintCollisionChecker --------------------------------------------------------------

def checker(cells: dict[tuple[int, int], int] | None = None) -> FootprintCollisionChecker:
    result = FootprintCollisionChecker()
    result.setCostmap(PyCostmap2D(grid(10, 10, 1.0, (0, 0), cells)))
    return result


def test_checker_without_costmap_says_how_to_set_one():
    fresh = FootprintCollisionChecker()
    for query in (lambda: fresh.worldToMapValidated(1.0, 1.0), lambda: fresh.pointCost(1, 1)):
        with pytest.raises(ValueError, match='use setCostmap to specify the costmap first'):
            query()


def test_footprint_cost_is_the_highest_cost_on_its_edges_not_inside():
    square = polygon((2, 2), (6, 2), (6, 6), (2, 6))
    assert checker().footprintCost(square) == 0.0
    assert checker({(4, 4): 99}).footprintCost(square) == 0.0  # inside, off every edge
    assert checker({(6, 4): 90, (3, 6): 60}).footprintCost(square) == 90.0
    # A grid cell of -2 is cost 254 (the int8 cells read as uint8): lethal.
    assert checker({(2, 5): -2}).footprintCost(square) == LETHAL_OBSTACLE


def test_footprint_cost_is_lethal_when_a_vertex_leaves_the_map():
    assert checker().footprintCost(polygon((1, 1), (5, 1), (12, 3))) == LETHAL_OBSTACLE
    assert checker().footprintCost(polygon((1, 1), (5, 1), (3, -0.5))) == LETHAL_OBSTACLE


def test_footprint_with_two_vertices_in_one_cell_costs_that_cell():
    assert checker({(3, 3): 90}).footprintCost(polygon((3.2, 3.2), (3.8, 3.7))) == 90.0


def test_footprint_cost_at_pose_rotates_then_moves_the_footprint():
    bar = polygon((0, 0), (3, 0))  # a 3 m bar along the robot's x axis
    costs = checker({(5, 8): 77})
    assert costs.footprintCostAtPose(5.0, 5.0, 0.0, bar) == 0.0
    assert costs.footprintCostAtPose(5.2, 5.2, math.pi / 2, bar) == 77.0
    assert costs.lineCost(5, 5, 5, 8) == 77.0  # x0, x1, y0, y1: upstream's argument order
