"""Costmap2DROS: a layered costmap in its own lifecycle node, as Nav2's global/local costmap.

Parameters are read as a Nav2 params file gives them (`global_costmap: global_costmap:
ros__parameters:`) and handed to build_costmap(). The static layer takes `map_topic`
(transient local), the obstacle layer its `observation_sources` (LaserScan), the robot pose
comes from TF (global_frame -> robot_base_frame). Out: `costmap` (OccupancyGrid, transient
local reliable), `costmap_raw` (nav2_msgs/Costmap), `published_footprint`, and the services
`get_costmap`, `clear_entirely_<name>`, `clear_around_<name>`, `clear_except_<name>`.
"""

from __future__ import annotations

import math
import threading
from typing import Any

from geometry_msgs.msg import Point32, PolygonStamped
from nav2_msgs.msg import Costmap
from nav2_msgs.srv import (
    ClearCostmapAroundRobot,
    ClearCostmapExceptRegion,
    ClearEntireCostmap,
    GetCostmap,
)
from nav2_util.lifecycle_node import LifecycleNode
from nav_msgs.msg import OccupancyGrid
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup
from rclpy.duration import Duration
from rclpy.lifecycle import State, TransitionCallbackReturn
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy, qos_profile_sensor_data
from rclpy.time import Time
from sensor_msgs.msg import LaserScan
from tf2_ros import TransformException
from tf2_ros.buffer import Buffer
from tf2_ros.transform_listener import TransformListener

from nav2_costmap_2d.clear_costmap import clear_entirely, clear_region
from nav2_costmap_2d.costmap_config import CostmapConfig, build_costmap
from nav2_costmap_2d.costmap_layer import ParameterError
from nav2_costmap_2d.footprint import transform_footprint
from nav2_costmap_2d.messages import costmap_raw_fields, occupancy_grid, take_map, take_scan
from nav2_costmap_2d.obstacle_layer import ObstacleLayer
from nav2_costmap_2d.static_layer import StaticLayer

LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                     reliability=ReliabilityPolicy.RELIABLE)
Pose = tuple[float, float, float]


def _yaw(q: Any) -> float:
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


class Costmap2DROS(LifecycleNode):
    """A costmap node (`global_costmap` in namespace `global_costmap`, as planner_server's)."""

    def __init__(self, name: str = 'global_costmap', namespace: str | None = None) -> None:
        # The layers' names are only known from `plugins`: every given parameter is read.
        super().__init__(name, namespace=namespace if namespace is not None else name,
                         allow_undeclared_parameters=True)
        if self._autostart_timer is not None:
            # a process-wide `-p autostart_node:=true` is meant for the server that owns us
            self._autostart_timer.cancel()
        self.get_logger().info('Creating Costmap')
        self.lock = threading.RLock()  # the planner reads the grid the update timer writes
        self.config: CostmapConfig | None = None
        self._handles: list[Any] = []
        self._timers: list[Any] = []
        self.tf_buffer: Buffer | None = None
        self._tf_listener: TransformListener | None = None
        self._costmap_pub = self._raw_pub = self._footprint_pub = None
        self._group = MutuallyExclusiveCallbackGroup()
        self._stale = True
        self._robot_pose: Pose | None = None

    @property
    def global_frame(self) -> str:
        return self.config.settings['global_frame'] if self.config else 'map'

    @property
    def costmap(self) -> Any:
        return self.config.layered.costmap

    # --- lifecycle -----------------------------------------------------------------------
    def on_configure(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Configuring')
        params = {name: p.value for name, p in self._parameter_overrides.items()
                  if name not in ('use_sim_time', 'autostart_node', 'bond_heartbeat_period')}
        try:
            self.config = build_costmap(params, self.get_name())
        except ParameterError as error:
            self.get_logger().error(str(error))
            return TransitionCallbackReturn.FAILURE
        for line in self.config.messages:
            self.get_logger().warning(line)
        settings = self.config.settings
        for plugin, kind in self.config.plugin_types.items():
            self.get_logger().info(f'Using plugin "{plugin}" of type {kind}')
        self.tf_buffer = Buffer()
        self._tf_listener = TransformListener(self.tf_buffer, self, spin_thread=False)
        for layer in self.config.layered.plugins:
            if isinstance(layer, StaticLayer):
                topic = '/' + str(layer.map_topic or settings['map_topic']).lstrip('/')
                self.get_logger().info(f'Subscribing to the map topic ({topic}) with '
                                       'transient local durability')
                self._handles.append(self.create_subscription(
                    OccupancyGrid, topic, lambda msg, layer=layer: self._on_map(layer, msg),
                    LATCHED, callback_group=self._group))
            elif isinstance(layer, ObstacleLayer):
                for source in layer.sources.values():
                    self.get_logger().info(
                        f'Creating an observation buffer for source {source.name}, topic '
                        f'{source.topic}, frame {source.sensor_frame}')
                    self._handles.append(self.create_subscription(
                        LaserScan, source.topic,
                        lambda msg, layer=layer, name=source.name: self._on_scan(
                            layer, name, msg), qos_profile_sensor_data,
                        callback_group=self._group))
        self._costmap_pub = self.create_lifecycle_publisher(OccupancyGrid, 'costmap', LATCHED)
        self._raw_pub = self.create_lifecycle_publisher(Costmap, 'costmap_raw', LATCHED)
        self._footprint_pub = self.create_lifecycle_publisher(
            PolygonStamped, 'published_footprint', 1)
        name = self.get_name()
        self._handles += [
            self.create_service(GetCostmap, 'get_costmap', self._on_get_costmap,
                                callback_group=self._group),
            self.create_service(ClearEntireCostmap, f'clear_entirely_{name}',
                                self._on_clear_entirely, callback_group=self._group),
            self.create_service(ClearCostmapAroundRobot, f'clear_around_{name}',
                                self._on_clear_around, callback_group=self._group),
            self.create_service(ClearCostmapExceptRegion, f'clear_except_{name}',
                                self._on_clear_except, callback_group=self._group),
        ]
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Activating')
        result = super().on_activate(state)
        settings = self.config.settings
        self._timers = [
            self.create_timer(1.0 / max(settings['update_frequency'], 1e-3), self._on_update,
                              callback_group=self._group),
            self.create_timer(1.0 / max(settings['publish_frequency'], 1e-3), self._on_publish,
                              callback_group=self._group)]
        return result

    def on_deactivate(self, state: State) -> TransitionCallbackReturn:
        for timer in self._timers:
            self.destroy_timer(timer)
        self._timers = []
        return super().on_deactivate(state)

    def release(self) -> None:
        for handle in self._handles:
            if hasattr(handle, 'srv_type'):
                self.destroy_service(handle)
            else:
                self.destroy_subscription(handle)
        for pub in (self._costmap_pub, self._raw_pub, self._footprint_pub):
            if pub is not None:
                self.destroy_lifecycle_publisher(pub)
        self._handles, self._costmap_pub, self._raw_pub, self._footprint_pub = [], None, None, None
        self._tf_listener = self.tf_buffer = None
        self.config = None

    # --- data in -------------------------------------------------------------------------
    def _on_map(self, layer: StaticLayer, msg: OccupancyGrid) -> None:
        self.get_logger().info(f'StaticLayer: Resizing costmap to {msg.info.width} X '
                               f'{msg.info.height} at {msg.info.resolution:f} m/pix')
        with self.lock:
            take_map(layer, msg)
            self._stale = True  # not current until an update has layered the new map in

    def _on_scan(self, layer: ObstacleLayer, source: str, msg: LaserScan) -> None:
        sensor = self.lookup_pose(msg.header.frame_id)
        if sensor is None:
            return
        with self.lock:
            take_scan(layer, source, msg, sensor,
                      Time.from_msg(msg.header.stamp).nanoseconds * 1e-9)

    def lookup_pose(self, frame: str) -> Pose | None:
        """`frame`'s origin in the global frame, from the latest TF (None: logged)."""
        if self.tf_buffer is None:
            return None
        try:
            t = self.tf_buffer.lookup_transform(
                self.global_frame, frame, Time(),
                Duration(seconds=self.config.settings['transform_tolerance']))
        except TransformException as error:
            self.get_logger().warning(
                f'Robot is not in {self.global_frame} frame: {error}',
                throttle_duration_sec=1.0)
            return None
        tr = t.transform
        return tr.translation.x, tr.translation.y, _yaw(tr.rotation)

    def get_robot_pose(self) -> Pose | None:
        return self.lookup_pose(self.config.settings['robot_base_frame'])

    # --- the update and publish loops ----------------------------------------------------
    def _on_update(self) -> None:
        pose = self.get_robot_pose()
        if pose is None:
            return
        with self.lock:
            self.config.layered.update_map(*pose)
            self._robot_pose = pose
            self._stale = False

    def is_current(self) -> bool:
        with self.lock:
            if self.config is None or self._stale or not self.config.layered.initialized:
                return False
            return self.config.layered.is_current() and all(
                layer.map_received for layer in self.config.layered.plugins
                if isinstance(layer, StaticLayer))

    def _on_publish(self) -> None:
        if not self.config.layered.initialized:
            return
        stamp = self.get_clock().now().to_msg()
        with self.lock:
            grid = occupancy_grid(self.costmap, self.global_frame, stamp,
                                  self.config.settings['map_vis_z'])
            raw = self._costmap_msg(stamp)
            pose = self._robot_pose
            footprint = transform_footprint(*pose, self.config.layered.footprint) \
                if pose else []
        self._costmap_pub.publish(grid)
        self._raw_pub.publish(raw)
        polygon = PolygonStamped()
        polygon.header.frame_id, polygon.header.stamp = self.global_frame, stamp
        polygon.polygon.points = [Point32(x=float(x), y=float(y)) for x, y in footprint]
        self._footprint_pub.publish(polygon)

    def _costmap_msg(self, stamp: Any) -> Costmap:
        fields = costmap_raw_fields(self.costmap)
        msg = Costmap()
        msg.header.frame_id, msg.header.stamp = self.global_frame, stamp
        meta = msg.metadata
        meta.update_time = stamp
        meta.layer = fields['layer']
        meta.resolution = fields['resolution']
        meta.size_x, meta.size_y = fields['size_x'], fields['size_y']
        meta.origin.position.x, meta.origin.position.y = fields['origin_x'], fields['origin_y']
        meta.origin.orientation.w = 1.0
        msg.data = fields['data']
        return msg

    # --- services ------------------------------------------------------------------------
    def _on_get_costmap(self, request: GetCostmap.Request, response: GetCostmap.Response
                        ) -> GetCostmap.Response:
        with self.lock:
            response.map = self._costmap_msg(self.get_clock().now().to_msg())
        return response

    def _on_clear_entirely(self, request: Any, response: Any) -> Any:
        self.get_logger().info(f'Received request to clear entirely the {self.get_name()}')
        with self.lock:
            clear_entirely(self.config.layered)
        return response

    def _clear(self, reset_distance: float, invert: bool) -> None:
        pose = self.get_robot_pose()
        if pose is None:
            self.get_logger().error('Cannot clear map because robot pose cannot be retrieved.')
            return
        with self.lock:
            clear_region(self.config.layered, pose[0], pose[1], reset_distance, invert)

    def _on_clear_around(self, request: Any, response: Any) -> Any:
        self.get_logger().info(f'Received request to clear around robot the {self.get_name()}')
        self._clear(request.reset_distance, False)
        return response

    def _on_clear_except(self, request: Any, response: Any) -> Any:
        self.get_logger().info(
            f'Received request to clear except a region the {self.get_name()}')
        self._clear(request.reset_distance, True)
        return response
