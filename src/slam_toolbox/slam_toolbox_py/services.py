"""slam_toolbox's services, with upstream's names and lines: save_map, serialize_map,
deserialize_map, pause_new_measurements, reset, dynamic_map, and the interactive mode's
clear_changes, toggle_interactive_mode and manual_loop_closure (no RViz panel here to move
nodes with: they answer and say so)."""

from __future__ import annotations

from nav2_map_server.map_io import MapMode, SaveParameters, save_map_to_file
from nav_msgs.srv import GetMap
from rclpy.parameter import Parameter

from slam_toolbox.srv import (
    Clear,
    DeserializePoseGraph,
    LoopClosure,
    Pause,
    Reset,
    SaveMap,
    SerializePoseGraph,
    ToggleInteractive,
)
from slam_toolbox_py import serialization


class ServicesMixin:
    """The services of SlamToolbox (slam_toolbox_node.py), which holds the state."""

    def create_services(self) -> list:
        services = [
            (SaveMap, 'slam_toolbox/save_map', self.on_save_map),
            (SerializePoseGraph, 'slam_toolbox/serialize_map', self.on_serialize_map),
            (DeserializePoseGraph, 'slam_toolbox/deserialize_map', self.on_deserialize_map),
            (Pause, 'slam_toolbox/pause_new_measurements', self.on_pause_new_measurements),
            (Reset, 'slam_toolbox/reset', self.on_reset),
            (GetMap, 'slam_toolbox/dynamic_map', self.on_dynamic_map),
            (Clear, 'slam_toolbox/clear_changes', self.on_clear_changes),
            (ToggleInteractive, 'slam_toolbox/toggle_interactive_mode',
             self.on_toggle_interactive_mode),
            (LoopClosure, 'slam_toolbox/manual_loop_closure', self.on_manual_loop_closure),
        ]
        return [self.create_service(kind, name, callback) for kind, name, callback in services]

    def on_save_map(self, request: SaveMap.Request, response: SaveMap.Response
                    ) -> SaveMap.Response:
        grid = self.last_map
        if grid is None:
            self.get_logger().warning('Map Saver: Cannot save map, no map yet received on '
                                      f"topic {self.values['map_name']}.")
            response.result = SaveMap.Response.RESULT_NO_MAP_RECEIEVD
            return response
        name = request.name.data
        if name:
            self.get_logger().info(f'SlamToolbox: Saving map as {name}.')
        else:
            self.get_logger().info('SlamToolbox: Saving map in current directory.')
        # map_saver_cli's defaults, written by nav2_map_server's own writer (upstream runs
        # `ros2 run nav2_map_server map_saver_cli -f <name>` for the same files)
        saved = save_map_to_file(grid, SaveParameters(
            map_file_name=name, image_format='pgm', free_thresh=0.25, occupied_thresh=0.65,
            mode=MapMode.TRINARY))
        response.result = (SaveMap.Response.RESULT_SUCCESS if saved
                           else SaveMap.Response.RESULT_UNDEFINED_FAILURE)
        return response

    def on_serialize_map(self, request: SerializePoseGraph.Request,
                         response: SerializePoseGraph.Response) -> SerializePoseGraph.Response:
        with self.lock:
            try:
                if self.mapper is None:
                    raise OSError('not configured')
                serialization.write(request.filename, self.mapper, self.values['resolution'])
                response.result = SerializePoseGraph.Response.RESULT_SUCCESS
            except (OSError, ValueError) as error:
                self.get_logger().error(f'Failed to serialize the pose graph to '
                                        f'{request.filename!r}: {error}')
                response.result = SerializePoseGraph.Response.RESULT_FAILED_TO_WRITE_FILE
                return response
        graph, data = serialization.paths(request.filename)
        self.get_logger().info(f'Serialized the pose graph to {graph} and {data}')
        return response

    def on_deserialize_map(self, request: DeserializePoseGraph.Request,
                           response: DeserializePoseGraph.Response
                           ) -> DeserializePoseGraph.Response:
        if (request.match_type == DeserializePoseGraph.Request.LOCALIZE_AT_POSE
                and self.values.get('mode') != 'localization'):
            self.get_logger().warning('Requested a localization deserialization in '
                                      'non-localization mode.')
            return response
        self.deserialize(request)
        return response

    def on_pause_new_measurements(self, request: Pause.Request, response: Pause.Response
                                  ) -> Pause.Response:
        paused = not self.get_parameter('paused_new_measurements').value
        self.set_parameters([Parameter('paused_new_measurements', value=paused)])
        self.get_logger().info('SlamToolbox: Toggled to ' + (
            'pause taking new measurements.' if paused
            else 'actively taking new measurements.'))
        response.status = True
        return response

    def on_reset(self, request: Reset.Request, response: Reset.Response) -> Reset.Response:
        with self.lock:
            if self.mapper is not None:
                self.mapper.reset()
                self.map_to_odom = None
                self.graph_generation += 1
        if request.pause_new_measurements:
            self.set_parameters([Parameter('paused_new_measurements', value=True)])
            self.get_logger().info('SlamToolbox: Toggled to pause taking new measurements '
                                   'after reset.')
        response.result = Reset.Response.RESULT_SUCCESS
        return response

    def on_dynamic_map(self, request: GetMap.Request, response: GetMap.Response
                       ) -> GetMap.Response:
        if self.last_map is not None:
            response.map = self.last_map
        return response

    def on_clear_changes(self, request: Clear.Request, response: Clear.Response
                         ) -> Clear.Response:
        # upstream forgets the nodes moved in RViz's interactive mode; none are moved here
        self.get_logger().info('LoopClosureAssistant: Clearing manual loop closure nodes.')
        return response

    def on_toggle_interactive_mode(self, request: ToggleInteractive.Request,
                                   response: ToggleInteractive.Response
                                   ) -> ToggleInteractive.Response:
        if not self.values.get('enable_interactive_mode'):
            self.get_logger().warning('Called toggle interactive mode with interactive mode '
                                      'disabled. Ignoring.')
            return response
        interactive = not self.get_parameter('interactive_mode').value
        self.set_parameters([Parameter('interactive_mode', value=interactive)])
        self.get_logger().info(f"SlamToolbox: Toggling {'on' if interactive else 'off'} "
                               'interactive mode (no interactive markers here: nodes cannot '
                               'be moved by hand).')
        return response

    def on_manual_loop_closure(self, request: LoopClosure.Request,
                               response: LoopClosure.Response) -> LoopClosure.Response:
        with self.lock:
            if self.mapper is not None and len(self.mapper.nodes) > 1:
                self.mapper.optimize()
                self.map_to_odom = self.mapper.map_to_odom()
        self.get_logger().info('LoopClosureAssistant: No nodes moved by hand: the graph was '
                               're-optimised as it is.')
        self.map_wake.set()
        return response
