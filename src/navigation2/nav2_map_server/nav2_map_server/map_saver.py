"""`ros2 run nav2_map_server map_saver_server`: Nav2's map saver, a lifecycle node (map_saver).

Configured, it offers `map_saver/save_map` (nav2_msgs/srv/SaveMap): it subscribes to the
requested map topic (transient local, reliable, depth 1 unless
`map_subscribe_transient_local` is false), waits up to `save_map_timeout` seconds for one
map and writes it with map_io. Thresholds left 0 take `free_thresh_default` and
`occupied_thresh_default`. map_saver_cli runs the same node for one map.
"""

from __future__ import annotations

import sys
import time
from dataclasses import replace

import rclpy
from nav2_msgs.srv import SaveMap
from nav2_util.lifecycle_node import LifecycleNode, run_server
from nav2_util.parameters import declare_checked, warn_unknown_parameters
from nav_msgs.msg import OccupancyGrid
from rclpy.executors import SingleThreadedExecutor
from rclpy.lifecycle import State, TransitionCallbackReturn
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

from nav2_map_server.map_io import (
    SaveParameters,
    map_mode_from_string,
    save_map_to_file,
    validate_save_parameters,
)

SAVE_MAP_SERVICE_NAME = 'save_map'
WAIT_SLICE = 0.1  # seconds: how often the wait for a map checks the clock and rclpy


class MapSaver(LifecycleNode):
    def __init__(self) -> None:
        super().__init__('map_saver')
        self.get_logger().info('Creating')
        declare_checked(self, 'save_map_timeout', 2.0)
        declare_checked(self, 'free_thresh_default', 0.25)
        declare_checked(self, 'occupied_thresh_default', 0.65)
        declare_checked(self, 'map_subscribe_transient_local', True)
        warn_unknown_parameters(self)
        self._save_map_service = None
        self._save_map_timeout = 2.0
        self._free_thresh_default = 0.25
        self._occupied_thresh_default = 0.65
        self._transient_local = True
        # Hears the maps save_map waits for (hidden: a leading underscore)
        self._listener = rclpy.create_node(
            f'_{self.get_name()}_map_listener', namespace=self.get_namespace(),
            context=self.context, start_parameter_services=False)

    def on_configure(self, state: State | None = None) -> TransitionCallbackReturn:
        self.get_logger().info('Configuring')
        self._save_map_timeout = self.get_parameter('save_map_timeout').value
        self._free_thresh_default = self.get_parameter('free_thresh_default').value
        self._occupied_thresh_default = self.get_parameter('occupied_thresh_default').value
        self._transient_local = self.get_parameter('map_subscribe_transient_local').value
        self._save_map_service = self.create_service(
            SaveMap, f'{self.get_name()}/{SAVE_MAP_SERVICE_NAME}', self._on_save_map)
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Activating')
        return super().on_activate(state)




    def release(self) -> None:
        if self._save_map_service is not None:
            self.destroy_service(self._save_map_service)
        self._save_map_service = None

    def _on_save_map(self, request: SaveMap.Request, response: SaveMap.Response
                     ) -> SaveMap.Response:
        save = SaveParameters(map_file_name=request.map_url, image_format=request.image_format,
                              free_thresh=request.free_thresh,
                              occupied_thresh=request.occupied_thresh)
        try:
            save.mode = map_mode_from_string(request.map_mode)
        except ValueError:
            self.get_logger().warning(
                f"Map mode parameter not recognized: '{request.map_mode}', using default "
                'value (trinary)')
        response.result = self.save_map_topic_to_file(request.map_topic, save)
        return response

    def save_map_topic_to_file(self, map_topic: str, save: SaveParameters) -> bool:
        """Wait for one map on `map_topic` and write it; False (one error line) otherwise."""
        self.get_logger().info(
            f"Saving map from '{map_topic}' topic to '{save.map_file_name}' file")
        if not map_topic:
            map_topic = 'map'
            self.get_logger().warning(
                f"Map topic unspecified. Map messages will be read from '{map_topic}' topic")
        save = replace(save)
        if save.free_thresh == 0.0:
            self.get_logger().warning('Free threshold unspecified. Setting it to default '
                                      f'value: {self._free_thresh_default:f}')
            save.free_thresh = self._free_thresh_default
        if save.occupied_thresh == 0.0:
            self.get_logger().warning('Occupied threshold unspecified. Setting it to default '
                                      f'value: {self._occupied_thresh_default:f}')
            save.occupied_thresh = self._occupied_thresh_default
        try:
            # bad thresholds or format: refused before waiting for a map that would be wasted
            validate_save_parameters(save)
        except ValueError as error:
            self.get_logger().error(f'Failed to save the map: {error}')
            return False
        grid = self._wait_for_map(map_topic)
        if grid is None:
            self.get_logger().error('Failed to spin map subscription')
            return False
        if save_map_to_file(grid, save):
            self.get_logger().info('Map saved successfully')
            return True
        self.get_logger().error('Failed to save the map')
        return False

    def _wait_for_map(self, map_topic: str) -> OccupancyGrid | None:
        """The first map on `map_topic` within save_map_timeout, heard by the listener node.

        The subscription lives on a node of its own, spun here: created, spun and destroyed
        by this one thread (rclpy fails an executor that waits on an entity another thread
        destroys), as upstream spins its own executor for it.
        """
        qos = QoSProfile(depth=10)
        if self._transient_local:
            qos = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                             reliability=ReliabilityPolicy.RELIABLE)
        received: list[OccupancyGrid] = []
        subscription = self._listener.create_subscription(
            OccupancyGrid, map_topic, received.append, qos)
        executor = SingleThreadedExecutor(context=self.context)
        executor.add_node(self._listener)
        deadline = time.monotonic() + self._save_map_timeout
        try:
            while not received and self.context.ok():
                remaining = deadline - time.monotonic()
                if remaining <= 0.0:
                    break
                executor.spin_once(timeout_sec=min(WAIT_SLICE, remaining))
        finally:
            executor.remove_node(self._listener)
            executor.shutdown()
            self._listener.destroy_subscription(subscription)
        return received[0] if received else None

    def destroy_node(self) -> None:
        super().destroy_node()
        self._listener.destroy_node()


def main(args: list[str] | None = None) -> int:
    return run_server(MapSaver, args)


if __name__ == '__main__':
    sys.exit(main())
