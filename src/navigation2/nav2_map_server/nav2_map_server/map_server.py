"""`ros2 run nav2_map_server map_server`: Nav2's map server, a lifecycle node.

On configure it loads `yaml_filename` (if not empty) and offers `map_server/map`
(nav_msgs/srv/GetMap) and `map_server/load_map` (nav2_msgs/srv/LoadMap); on activate it
publishes the map on `topic_name` (default `map`; reliable, transient local, depth 1, so a
late subscriber still gets it). A map that cannot be loaded gives one `map_io` error line and
the result code; the published map stays as it was.
"""

from __future__ import annotations

import sys

from nav2_msgs.srv import LoadMap
from nav2_util.lifecycle_node import LifecycleNode, run_server
from nav2_util.parameters import declare_checked, warn_unknown_parameters
from nav_msgs.msg import OccupancyGrid
from nav_msgs.srv import GetMap
from rclpy.lifecycle import State, TransitionCallbackReturn
from rclpy.parameter import Parameter
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

from nav2_map_server.map_io import LoadMapStatus, load_map_from_yaml

MAP_QOS = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                     reliability=ReliabilityPolicy.RELIABLE)
SERVICE_NAME = 'map'
LOAD_MAP_SERVICE_NAME = 'load_map'
RESULTS = {
    LoadMapStatus.LOAD_MAP_SUCCESS: LoadMap.Response.RESULT_SUCCESS,
    LoadMapStatus.MAP_DOES_NOT_EXIST: LoadMap.Response.RESULT_MAP_DOES_NOT_EXIST,
    LoadMapStatus.INVALID_MAP_METADATA: LoadMap.Response.RESULT_INVALID_MAP_METADATA,
    LoadMapStatus.INVALID_MAP_DATA: LoadMap.Response.RESULT_INVALID_MAP_DATA,
}


class MapServer(LifecycleNode):
    def __init__(self) -> None:
        super().__init__('map_server')
        self.get_logger().info('Creating')
        declare_checked(self, 'yaml_filename', Parameter.Type.STRING)
        declare_checked(self, 'topic_name', 'map')
        declare_checked(self, 'frame_id', 'map')
        warn_unknown_parameters(self)
        self._map: OccupancyGrid | None = None
        self._frame_id = 'map'
        self._publisher = None
        self._map_services = []

    def on_configure(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Configuring')
        yaml_filename = self.get_parameter('yaml_filename').value
        topic_name = self.get_parameter('topic_name').value
        self._frame_id = self.get_parameter('frame_id').value
        if yaml_filename is None:
            # upstream dies of an uninitialised parameter here; '' means "no map yet"
            self.get_logger().error(
                "Parameter 'yaml_filename' is not set: give the map's YAML file, or '' to "
                f'load one later through {self.get_name()}/{LOAD_MAP_SERVICE_NAME}')
            return TransitionCallbackReturn.FAILURE
        if yaml_filename:
            if self._load(yaml_filename)[0] != LoadMapStatus.LOAD_MAP_SUCCESS:
                return TransitionCallbackReturn.FAILURE
        else:
            self.get_logger().info("yaml-filename parameter is empty, set map through "
                                   f"'{LOAD_MAP_SERVICE_NAME}'-service")
        prefix = f'{self.get_name()}/'
        self._map_services = [
            self.create_service(GetMap, prefix + SERVICE_NAME, self._on_get_map),
            self.create_service(LoadMap, prefix + LOAD_MAP_SERVICE_NAME, self._on_load_map),
        ]
        self._publisher = self.create_lifecycle_publisher(OccupancyGrid, topic_name, MAP_QOS)
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Activating')
        result = super().on_activate(state)  # enables the lifecycle publisher
        if self._map is not None:
            self._publisher.publish(self._map)
        return result




    def release(self) -> None:
        if self._publisher is not None:
            self.destroy_lifecycle_publisher(self._publisher)
        for service in self._map_services:
            self.destroy_service(service)
        self._publisher, self._map_services = None, []
        self._map = None

    def _load(self, yaml_filename: str) -> tuple[LoadMapStatus, OccupancyGrid | None]:
        status, grid = load_map_from_yaml(yaml_filename, self.get_clock().now)
        if grid is not None:
            grid.header.frame_id = self._frame_id
            grid.header.stamp = grid.info.map_load_time = self.get_clock().now().to_msg()
            self._map = grid
        return status, grid

    def _on_get_map(self, _request: GetMap.Request, response: GetMap.Response
                    ) -> GetMap.Response:
        if not self.is_active():
            self.get_logger().warning(
                'Received GetMap request but not in ACTIVE state, ignoring!')
            return response
        self.get_logger().info('Handling GetMap request')
        if self._map is not None:
            response.map = self._map
        return response

    def _on_load_map(self, request: LoadMap.Request, response: LoadMap.Response
                     ) -> LoadMap.Response:
        if not self.is_active():
            self.get_logger().warning(
                'Received LoadMap request but not in ACTIVE state, ignoring!')
            response.result = LoadMap.Response.RESULT_UNDEFINED_FAILURE
            return response
        self.get_logger().info('Handling LoadMap request')
        status, grid = self._load(request.map_url)
        response.result = RESULTS[status]
        if grid is not None:
            response.map = grid
            self._publisher.publish(grid)
        return response


def main(args: list[str] | None = None) -> int:
    return run_server(MapServer, args)


if __name__ == '__main__':
    sys.exit(main())
