"""Costmaps to and from ROS messages, as Costmap2DPublisher and the layers' callbacks do."""

from __future__ import annotations

from array import array
from typing import Any

import numpy as np
from nav_msgs.msg import OccupancyGrid

from nav2_costmap_2d.costmap_2d import Costmap2D
from nav2_costmap_2d.obstacle_layer import ObstacleLayer
from nav2_costmap_2d.static_layer import StaticLayer


def occupancy_grid(costmap: Costmap2D, frame_id: str, stamp: Any = None,
                   map_vis_z: float = 0.0) -> OccupancyGrid:
    """The `costmap` topic's message (prepareGrid): costs translated to -1 and 0..100."""
    grid = OccupancyGrid()
    grid.header.frame_id = frame_id
    if stamp is not None:
        grid.header.stamp = stamp
    grid.info.resolution = float(costmap.resolution)
    grid.info.width = costmap.size_x
    grid.info.height = costmap.size_y
    grid.info.origin.position.x, grid.info.origin.position.y = costmap.occupancy_origin()
    grid.info.origin.position.z = float(map_vis_z)
    grid.info.origin.orientation.w = 1.0
    grid.data = array('b', costmap.to_occupancy_data().tobytes())
    return grid


def costmap_raw_fields(costmap: Costmap2D) -> dict[str, Any]:
    """nav2_msgs/Costmap's content (prepareCostmap): metadata and the raw costs as bytes."""
    origin_x, origin_y = costmap.occupancy_origin()
    return {'layer': 'master', 'resolution': float(costmap.resolution),
            'size_x': costmap.size_x, 'size_y': costmap.size_y,
            'origin_x': origin_x, 'origin_y': origin_y, 'data': costmap.costmap.tobytes()}


def take_map(layer: StaticLayer, grid: OccupancyGrid) -> None:
    """StaticLayer::incomingMap for a map message (its frame taken as the costmap's)."""
    info = grid.info
    layer.process_map(info.width, info.height, info.resolution, info.origin.position.x,
                      info.origin.position.y,
                      np.frombuffer(memoryview(grid.data).cast('B'), dtype=np.uint8))


def take_scan(layer: ObstacleLayer, source: str, scan: Any,
              sensor_pose: tuple[float, float, float], stamp: float = 0.0) -> None:
    """A sensor_msgs/LaserScan of `source`, its sensor at sensor_pose in the costmap's frame."""
    layer.add_scan(source, scan.ranges, scan.angle_min, scan.angle_increment, scan.range_min,
                   scan.range_max, sensor_pose, stamp)
