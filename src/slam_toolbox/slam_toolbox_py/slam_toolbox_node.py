"""slam_toolbox's node (`SlamToolbox`, the base of the async and sync nodes): a lifecycle
node named slam_toolbox with upstream's parameters, topics, services and log lines.

Scans arrive on the executor; a worker thread turns them into graph nodes (mapper.py), a
map thread rasters the graph every map_update_interval and publishes `/map` and
`/map_metadata` (transient local, reliable) and `slam_toolbox/graph_visualization`, and a
timer sends map -> odom every transform_publish_period, stamped transform_timeout after the
latest scan. How scans reach the worker is the subclass's: the async node keeps only the
newest (older ones waiting are dropped and counted), the sync node queues them all.
"""

from __future__ import annotations

import threading
import time

import numpy as np
from geometry_msgs.msg import PoseWithCovarianceStamped
from lifecycle_msgs.msg import State as StateMsg
from nav2_util.parameters import declare_checked, warn_unknown_parameters
from nav_msgs.msg import MapMetaData, OccupancyGrid
from node_runtime.rclcpp_parity import RclcppLifecycleTransitions
from rclpy.duration import Duration
from rclpy.exceptions import ParameterUninitializedException
from rclpy.lifecycle import Node, State, TransitionCallbackReturn
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy, qos_profile_sensor_data
from rclpy.time import Time
from sensor_msgs.msg import LaserScan
from tf2_ros.buffer import Buffer
from tf2_ros.transform_broadcaster import TransformBroadcaster
from tf2_ros.transform_listener import TransformListener
from visualization_msgs.msg import MarkerArray

from slam_toolbox.srv import DeserializePoseGraph
from slam_toolbox_py import messages, serialization
from slam_toolbox_py.mapper import Mapper
from slam_toolbox_py.occupancy import OccupancyMap
from slam_toolbox_py.parameters import STATE, all_defaults, mapper_params
from slam_toolbox_py.services import ServicesMixin

LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                     reliability=ReliabilityPolicy.RELIABLE)


class SlamToolbox(ServicesMixin, RclcppLifecycleTransitions, Node):
    def __init__(self) -> None:
        super().__init__('slam_toolbox')
        if 'stack_size_to_use' in self._parameter_overrides:
            value = self._parameter_overrides['stack_size_to_use'].value
            self.get_logger().info(f'Node using stack size {value}')
        for name, default in {**all_defaults(), **STATE}.items():
            declare_checked(self, name, default)
        warn_unknown_parameters(self)
        self.values: dict = {}
        self.mapper: Mapper | None = None
        self.lock = threading.Lock()  # the mapper, between the worker, map and services
        self.stop = threading.Event()
        self.map_wake = threading.Event()
        self.threads: list[threading.Thread] = []
        self.handles: list = []
        self.graph_generation = 0  # bumped when the graph is replaced: the map is redone
        self.localization = False
        self.scan_header = None
        self.map_to_odom: np.ndarray | None = None  # the worker's latest, for the TF timer
        self.last_map: OccupancyGrid | None = None
        self.lasers: dict[str, np.ndarray] = {}
        self.dropped = 0
        self.scan_count = 0
        self.last_taken: float | None = None
        self.nan_logged = False
        self.tf_listener = None

    def value(self, name: str):
        """The parameter's value; None for one declared without a default and not given."""
        try:
            return self.get_parameter(name).value
        except ParameterUninitializedException:
            return None

    # -- lifecycle ------------------------------------------------------------------------
    def on_configure(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Configuring')
        v = {name: self.value(name) for name in all_defaults()}
        if v['resolution'] <= 0.0:
            self.get_logger().warning(
                "You've set resolution of map to be zero or negative,this isn't allowed so "
                'it will be set to default value 0.05.')
            v['resolution'] = 0.05
        if v['throttle_scans'] <= 0:
            self.get_logger().warning(
                "You've set throttle_scans to be zero,this isn't allowed so it will be set "
                'to default value 1.')
            v['throttle_scans'] = 1
        if v['map_update_interval'] <= 0.0:
            self.get_logger().warning('map_update_interval must be above 0: using 10.0')
            v['map_update_interval'] = 10.0
        self.values = v
        self.localization = v['mode'] == 'localization'
        if v['mode'] not in ('mapping', 'localization'):
            self.get_logger().error(f"mode '{v['mode']}' is not one of mapping, "
                                    'localization: mapping')
        self.mapper = Mapper(mapper_params(v))
        self.get_logger().info(f"Using solver plugin {v['solver_plugin']}")
        self.tf_buffer = Buffer(cache_time=Duration(seconds=v['tf_buffer_duration']))
        self.tf_listener = TransformListener(self.tf_buffer, self, spin_thread=True)
        self.tf_broadcaster = TransformBroadcaster(self)
        self.stop.clear()
        self.load_pose_graph_by_params()
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Activating')
        v = self.values
        self.pose_pub = self.create_publisher(PoseWithCovarianceStamped, 'pose', 10)
        self.map_pub = self.create_publisher(OccupancyGrid, v['map_name'], LATCHED)
        self.meta_pub = self.create_publisher(MapMetaData, v['map_name'] + '_metadata',
                                              LATCHED)
        self.graph_pub = self.create_publisher(MarkerArray, 'slam_toolbox/graph_visualization',
                                               1)
        self.handles = [self.pose_pub, self.map_pub, self.meta_pub, self.graph_pub,
                        self.create_subscription(LaserScan, v['scan_topic'], self.on_scan,
                                                 qos_profile_sensor_data)]
        self.handles += self.create_services()
        if v['transform_publish_period'] > 0:
            self.handles.append(self.create_timer(v['transform_publish_period'],
                                                  self.publish_transform))
        self.stop.clear()
        self.threads = [threading.Thread(target=self.guarded, args=(self.process_scans,),
                                         daemon=True, name='slam_toolbox_scans'),
                        threading.Thread(target=self.guarded, args=(self.publish_maps,),
                                         daemon=True, name='slam_toolbox_map')]
        for thread in self.threads:
            thread.start()
        return TransitionCallbackReturn.SUCCESS

    def on_deactivate(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Deactivating')
        self.stop_threads()
        for handle in self.handles:
            self._destroy(handle)
        self.handles = []
        return TransitionCallbackReturn.SUCCESS

    def on_cleanup(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Cleaning up')
        self.release()
        return TransitionCallbackReturn.SUCCESS

    def on_shutdown(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Shutting down')
        self.stop_threads()
        self.release()
        return TransitionCallbackReturn.SUCCESS

    def _LifecycleNodeMixin__execute_callback(self, current_state_id, previous_state):
        # rclpy turns an exception in on_configure & co. into ERROR without a word
        callback = self._callbacks.get(current_state_id)
        if callback is None:
            return TransitionCallbackReturn.SUCCESS
        try:
            return callback(previous_state)
        except Exception as error:  # any failure is the transition's failure
            self.get_logger().error(f'Caught exception in callback for transition: {error}')
            return TransitionCallbackReturn.ERROR

    def _destroy(self, handle) -> None:
        if handle in self._services:
            self.destroy_service(handle)
        elif handle in self._timers:
            self.destroy_timer(handle)
        elif handle in self._subscriptions:
            self.destroy_subscription(handle)
        elif handle in self._publishers:
            self.destroy_publisher(handle)

    def release(self) -> None:
        if self.tf_listener is not None:  # its thread first, then its node
            self.tf_listener._stop_spinning()
            self.tf_listener.unregister()
            self.tf_listener.node.destroy_node()
            self.tf_listener = None
        self.mapper = None
        self.lasers.clear()

    def stop_threads(self) -> None:
        self.stop.set()
        self.map_wake.set()
        self.wake_worker()
        for thread in self.threads:
            thread.join(timeout=5.0)
        self.threads = []
        if self.dropped:
            self.get_logger().info(f'{self.dropped} scans were dropped: they arrived while '
                                   'the previous ones were still being processed')

    def destroy_node(self) -> None:
        state = self._state_machine.current_state[0]
        if state == StateMsg.PRIMARY_STATE_ACTIVE:
            self.trigger_deactivate()
            state = self._state_machine.current_state[0]
        if state == StateMsg.PRIMARY_STATE_INACTIVE:
            self.trigger_cleanup()
        super().destroy_node()

    def guarded(self, loop) -> None:
        try:
            loop()
        except Exception as error:  # a thread's death would silently stop the mapping
            self.get_logger().error(f'{loop.__name__} stopped: {error!r}')

    # -- scans ----------------------------------------------------------------------------
    def on_scan(self, msg: LaserScan) -> None:
        self.scan_header = msg.header
        if self.get_parameter('paused_new_measurements').value:
            return
        self.scan_count += 1
        if self.scan_count % self.values['throttle_scans']:
            return
        stamp = Time.from_msg(msg.header.stamp).nanoseconds / 1e9
        if (self.last_taken is not None and stamp >= self.last_taken
                and stamp - self.last_taken < self.values['minimum_time_interval']):
            return
        self.last_taken = stamp
        self.enqueue(msg)

    def enqueue(self, msg: LaserScan) -> None:
        raise NotImplementedError

    def wake_worker(self) -> None:
        raise NotImplementedError

    def next_scan(self) -> LaserScan | None:
        """The next scan to process, or None after a short wait."""
        raise NotImplementedError

    def process_scans(self) -> None:
        while not self.stop.is_set():
            msg = self.next_scan()
            if msg is None:
                continue
            try:
                self.add_scan(msg)
            except Exception as error:  # one bad scan must not end the mapping
                self.get_logger().error(f'Failed to process a scan: {error!r}',
                                        throttle_duration_sec=5.0)

    def laser_pose(self, msg: LaserScan) -> np.ndarray | None:
        frame = msg.header.frame_id
        if frame not in self.lasers:
            try:
                t = self.tf_buffer.lookup_transform(self.values['base_frame'], frame, Time(),
                                                    Duration(seconds=0.5))
            except Exception as error:  # tf2's lookup errors
                self.get_logger().error('Failed to compute laser pose, aborting '
                                        f'initialization ({error})',
                                        throttle_duration_sec=5.0)
                return None
            self.lasers[frame] = messages.pose2d(t.transform)
        return self.lasers[frame]

    def odom_pose(self, msg: LaserScan) -> np.ndarray | None:
        v = self.values
        try:
            t = self.tf_buffer.lookup_transform(v['odom_frame'], v['base_frame'],
                                                Time.from_msg(msg.header.stamp),
                                                Duration(seconds=v['transform_timeout']))
        except Exception:  # tf2's lookup errors: no odometry at this stamp
            self.get_logger().warning('Failed to compute odom pose', throttle_duration_sec=5.0)
            return None
        return messages.pose2d(t.transform)

    def add_scan(self, msg: LaserScan) -> None:
        laser = self.laser_pose(msg)
        if laser is None:
            self.get_logger().warning('Failed to create laser device for '
                                      f'{msg.header.frame_id}; discarding scan',
                                      throttle_duration_sec=5.0)
            return
        odom = self.odom_pose(msg)
        if odom is None:
            return
        hits, misses, bad = messages.scan_points(msg, laser, self.values['max_laser_range'])
        if bad and not self.nan_logged:
            self.nan_logged = True
            self.get_logger().warning(f'Scan has {bad} NaN ranges: left out (said once)')
        stamp = Time.from_msg(msg.header.stamp).nanoseconds / 1e9
        with self.lock:
            mapper = self.mapper
            if mapper is None:
                return
            if self.localization:
                pose = mapper.localize(odom, hits, stamp)
                cov = np.diag([0.01, 0.01, 0.001])
            else:
                node = mapper.process(odom, hits, misses, laser[:2], stamp)
                pose = None if node is None else node.pose
                cov = None if node is None else node.covariance
            self.map_to_odom = mapper.map_to_odom()
        if pose is not None:
            self.publish_pose(pose, cov, msg.header.stamp)
            if not self.localization and len(mapper.nodes) == 1:
                self.map_wake.set()  # the first map without waiting map_update_interval

    def publish_pose(self, pose: np.ndarray, cov: np.ndarray, stamp) -> None:
        msg = PoseWithCovarianceStamped()
        msg.header.frame_id, msg.header.stamp = self.values['map_frame'], stamp
        msg.pose.pose = messages.pose_msg(pose)
        c = [0.0] * 36
        p, y = self.values['position_covariance_scale'], self.values['yaw_covariance_scale']
        c[0], c[1], c[6], c[7] = (cov[0, 0] * p, cov[0, 1] * p, cov[1, 0] * p, cov[1, 1] * p)
        c[35] = cov[2, 2] * y
        msg.pose.covariance = [float(x) for x in c]
        self.pose_pub.publish(msg)

    def publish_transform(self) -> None:
        # no lock: the worker may hold it for a whole match, map -> odom must keep going
        header, map_to_odom = self.scan_header, self.map_to_odom
        if header is None or map_to_odom is None or not header.frame_id:
            return
        stamp = Time.from_msg(header.stamp) + Duration(seconds=self.values['transform_timeout'])
        if stamp.nanoseconds <= 0:
            return
        self.tf_broadcaster.sendTransform(messages.transform_msg(
            map_to_odom, self.values['map_frame'], self.values['odom_frame'], stamp.to_msg()))

    # -- the map --------------------------------------------------------------------------
    def publish_maps(self) -> None:
        v = self.values
        grid = OccupancyMap(v['resolution'], v['max_laser_range'], v['occupancy_threshold'],
                            v['min_pass_through'])
        known, generation = 0, -1
        while not self.stop.is_set():
            started = time.monotonic()
            with self.lock:
                mapper = self.mapper
                if mapper is None:
                    return
                if generation != self.graph_generation:
                    grid.clear()
                    known, generation = 0, self.graph_generation
                new = mapper.nodes[known:]
                known = len(mapper.nodes)
                poses = {n.id: n.pose.copy() for n in mapper.nodes}
                nodes, edges = list(mapper.nodes), list(mapper.edges)
            for n in new:
                grid.add(n.id, n.pose, n.hits, n.misses, n.origin)
            if poses:
                self.publish_map(grid, poses, nodes, edges)
            wait = v['map_update_interval'] - (time.monotonic() - started)
            self.map_wake.wait(timeout=max(0.05, wait))
            self.map_wake.clear()

    def publish_map(self, grid: OccupancyMap, poses: dict, nodes: list, edges: list) -> None:
        data, width, height, origin = grid.raster(poses)
        if width == 0:
            return
        header = self.scan_header
        stamp = header.stamp if header is not None else self.get_clock().now().to_msg()
        msg = messages.grid_msg(data, width, height, origin, self.values['resolution'],
                                self.values['map_frame'], stamp)
        self.last_map = msg
        self.map_pub.publish(msg)
        self.meta_pub.publish(msg.info)
        self.graph_pub.publish(messages.graph_markers(nodes, edges, self.values['map_frame'],
                                                      stamp))

    # -- serialized graphs ----------------------------------------------------------------
    def load_pose_graph_by_params(self) -> None:
        v = self.values
        filename = v['map_file_name']
        if not filename:
            if self.localization:
                self.get_logger().error('Localization mode needs map_file_name: a serialized '
                                        'pose graph to localize in')
            return
        pose = v['map_start_pose']
        if pose is not None and len(pose) != 3:
            self.get_logger().error(
                'LocalizationSlamToolbox: Incorrect number of arguments for map starting pose.'
                ' Must be in format: [x, y, theta]. Starting at the origin')
            pose = [0.0, 0.0, 0.0]
        if pose is None and v['map_start_at_dock'] is None:
            self.get_logger().error(
                'LocalizationSlamToolbox: Map starting pose not specified. Set either '
                'map_start_pose or map_start_at_dock.')
            return
        request = DeserializePoseGraph.Request(filename=filename)
        if self.localization:
            request.match_type = DeserializePoseGraph.Request.LOCALIZE_AT_POSE
        elif pose is None:
            request.match_type = DeserializePoseGraph.Request.START_AT_FIRST_NODE
        else:
            request.match_type = DeserializePoseGraph.Request.START_AT_GIVEN_POSE
        if pose is not None:
            request.initial_pose.x, request.initial_pose.y = float(pose[0]), float(pose[1])
            request.initial_pose.theta = float(pose[2])
        self.deserialize(request)

    def deserialize(self, request: DeserializePoseGraph.Request) -> bool:
        kinds = DeserializePoseGraph.Request
        if request.match_type not in (kinds.START_AT_FIRST_NODE, kinds.START_AT_GIVEN_POSE,
                                      kinds.LOCALIZE_AT_POSE):
            self.get_logger().error('Deserialization called without valid processor type '
                                    'set. Undefined behavior!')
            return False
        if not request.filename:
            self.get_logger().warning('No map file given!')
            return False
        fresh = Mapper(mapper_params(self.values))
        try:
            serialization.read(request.filename, fresh)
        except (OSError, ValueError) as error:
            self.get_logger().error(f'DeserializePoseGraph: Failed to read file: '
                                    f'{request.filename}. ({error})')
            return False
        p = request.initial_pose
        given = np.array([p.x, p.y, p.theta])
        fresh.start_at(None if request.match_type == kinds.START_AT_FIRST_NODE else given)
        with self.lock:
            self.mapper = fresh
            self.map_to_odom = None
            self.localization = request.match_type == kinds.LOCALIZE_AT_POSE
            self.graph_generation += 1
        self.get_logger().info(f'DeserializePoseGraph: read {len(fresh.nodes)} nodes and '
                               f'{len(fresh.edges)} edges from {request.filename}')
        self.map_wake.set()
        return True

