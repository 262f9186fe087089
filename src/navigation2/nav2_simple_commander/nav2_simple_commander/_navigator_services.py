"""BasicNavigator's service calls: map changes, costmap clearing and costmap queries.

BasicNavigator's base class (kept apart only for the modules' size): each call waits for
its service, logging upstream's line once a second, then blocks until the answer.
"""

from __future__ import annotations

import math
from numbers import Real
from typing import Any

import rclpy
from geometry_msgs.msg import PoseStamped
from nav2_msgs.msg import Costmap
from nav2_msgs.srv import (
    ClearCostmapAroundPose,
    ClearCostmapAroundRobot,
    ClearCostmapExceptRegion,
    ClearEntireCostmap,
    GetCostmap,
    LoadMap,
)
from rclpy.client import Client
from rclpy.node import Node


def finite_number(name: str, value: Any) -> float:
    """The argument as a float; refused, naming it, when it is no finite number.

    Checked before anything is sent: a bad argument changes nothing on the robot.
    """
    if isinstance(value, bool) or not isinstance(value, Real) or not math.isfinite(value):
        raise ValueError(f'{name} must be a finite number (int or float), got {value!r}')
    return float(value)


class NavigatorServices(Node):
    """changeMap, clear*Costmap*, get*Costmap and the log helpers of BasicNavigator."""

    def __init__(self, node_name: str, namespace: str) -> None:
        super().__init__(node_name=node_name, namespace=namespace)
        create = self.create_client
        self.change_maps_srv = create(LoadMap, 'map_server/load_map')
        self.clear_costmap_global_srv = create(
            ClearEntireCostmap, 'global_costmap/clear_entirely_global_costmap')
        self.clear_costmap_local_srv = create(
            ClearEntireCostmap, 'local_costmap/clear_entirely_local_costmap')
        self.clear_costmap_except_region_srv = create(
            ClearCostmapExceptRegion, 'local_costmap/clear_costmap_except_region')
        self.clear_costmap_around_robot_srv = create(
            ClearCostmapAroundRobot, 'local_costmap/clear_costmap_around_robot')
        self.clear_costmap_around_pose_srv = create(
            ClearCostmapAroundPose, 'local_costmap/clear_costmap_around_pose')
        self.get_costmap_global_srv = create(GetCostmap, 'global_costmap/get_costmap')
        self.get_costmap_local_srv = create(GetCostmap, 'local_costmap/get_costmap')

    def _call(self, client: Client, request: Any, waiting_line: str) -> Any:
        while not client.wait_for_service(timeout_sec=1.0):
            self.info(waiting_line)
        future = client.call_async(request)
        rclpy.spin_until_future_complete(self, future)
        return future.result()

    def changeMap(self, map_filepath: str) -> None:
        """Change the current static map in the map server."""
        response = self._call(self.change_maps_srv, LoadMap.Request(map_url=map_filepath),
                              'change map service not available, waiting...')
        if response.result != LoadMap.Response.RESULT_SUCCESS:
            self.error('Change map request failed!')
        else:
            self.info('Change map request was successful!')

    def clearAllCostmaps(self) -> None:
        """Clear all costmaps."""
        self.clearLocalCostmap()
        self.clearGlobalCostmap()

    def clearLocalCostmap(self) -> None:
        """Clear local costmap."""
        self._call(self.clear_costmap_local_srv, ClearEntireCostmap.Request(),
                   'Clear local costmaps service not available, waiting...')

    def clearGlobalCostmap(self) -> None:
        """Clear global costmap."""
        self._call(self.clear_costmap_global_srv, ClearEntireCostmap.Request(),
                   'Clear global costmaps service not available, waiting...')

    def clearCostmapExceptRegion(self, reset_distance: float) -> None:
        """Clear the costmap except for a specified region."""
        self._call(self.clear_costmap_except_region_srv,
                   ClearCostmapExceptRegion.Request(
                       reset_distance=finite_number('reset_distance', reset_distance)),
                   'ClearCostmapExceptRegion service not available, waiting...')

    def clearCostmapAroundRobot(self, reset_distance: float) -> None:
        """Clear the costmap around the robot."""
        self._call(self.clear_costmap_around_robot_srv,
                   ClearCostmapAroundRobot.Request(
                       reset_distance=finite_number('reset_distance', reset_distance)),
                   'ClearCostmapAroundRobot service not available, waiting...')

    def clearCostmapAroundPose(self, pose: PoseStamped, reset_distance: float) -> None:
        """Clear the costmap around a specified pose."""
        self._call(self.clear_costmap_around_pose_srv,
                   ClearCostmapAroundPose.Request(
                       pose=pose, reset_distance=finite_number('reset_distance', reset_distance)),
                   'ClearCostmapAroundPose service not available, waiting...')

    def getGlobalCostmap(self) -> Costmap:
        """Get the global costmap."""
        return self._call(self.get_costmap_global_srv, GetCostmap.Request(),
                          'Get global costmaps service not available, waiting...').map

    def getLocalCostmap(self) -> Costmap:
        """Get the local costmap."""
        return self._call(self.get_costmap_local_srv, GetCostmap.Request(),
                          'Get local costmaps service not available, waiting...').map

    def info(self, msg: str) -> None:
        self.get_logger().info(msg)

    def warn(self, msg: str) -> None:
        self.get_logger().warn(msg)

    def error(self, msg: str) -> None:
        self.get_logger().error(msg)

    def debug(self, msg: str) -> None:
        self.get_logger().debug(msg)
