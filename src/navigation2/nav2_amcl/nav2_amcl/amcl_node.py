"""`ros2 run nav2_amcl amcl`: Nav2's AMCL as a lifecycle node around AmclCore.

On configure it declares nothing new (the parameters are declared at construction, Nav2's
names and defaults) and builds the filter, its topics and services; on activate it takes
scans. Topics: `map` in (transient local), `scan` in (sensor data QoS), `initialpose` in,
`amcl_pose` out (transient local, reliable, depth 1), `particle_cloud` out; the map -> odom
transform on /tf, stamped transform_tolerance ahead of the scan; services
`reinitialize_global_localization` and `request_nomotion_update` (std_srvs/Empty).
"""

from __future__ import annotations

import math
import sys

import numpy as np
from geometry_msgs.msg import Pose, PoseWithCovarianceStamped, TransformStamped
from nav2_msgs.msg import Particle, ParticleCloud
from nav2_util.lifecycle_node import LifecycleNode, run_server
from nav2_util.parameters import declare_checked, warn_unknown_parameters
from nav_msgs.msg import OccupancyGrid
from rclpy.duration import Duration
from rclpy.lifecycle import State, TransitionCallbackReturn
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy, qos_profile_sensor_data
from rclpy.time import Time
from sensor_msgs.msg import LaserScan
from std_srvs.srv import Empty
from tf2_ros.buffer import Buffer
from tf2_ros.transform_broadcaster import TransformBroadcaster
from tf2_ros.transform_listener import TransformListener

from nav2_amcl.amcl_core import AmclCore, Estimate
from nav2_amcl.laser_model import laser_data
from nav2_amcl.motion_model import DIFFERENTIAL
from nav2_amcl.occupancy import AmclMap

LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                     reliability=ReliabilityPolicy.RELIABLE)
PARAMETERS = {
    'alpha1': 0.2, 'alpha2': 0.2, 'alpha3': 0.2, 'alpha4': 0.2, 'alpha5': 0.2,
    'base_frame_id': 'base_footprint', 'beam_skip_distance': 0.5,
    'beam_skip_error_threshold': 0.9, 'beam_skip_threshold': 0.3, 'do_beamskip': False,
    'global_frame_id': 'map', 'lambda_short': 0.1, 'laser_likelihood_max_dist': 2.0,
    'laser_max_range': 100.0, 'laser_min_range': -1.0, 'laser_model_type': 'likelihood_field',
    'set_initial_pose': False, 'initial_pose.x': 0.0, 'initial_pose.y': 0.0,
    'initial_pose.z': 0.0, 'initial_pose.yaw': 0.0, 'max_beams': 60, 'max_particles': 2000,
    'min_particles': 500, 'odom_frame_id': 'odom', 'pf_err': 0.05, 'pf_z': 0.99,
    'recovery_alpha_fast': 0.0, 'recovery_alpha_slow': 0.0, 'resample_interval': 1,
    'robot_model_type': DIFFERENTIAL, 'save_pose_rate': 0.5, 'sigma_hit': 0.2,
    'tf_broadcast': True, 'transform_tolerance': 1.0, 'update_min_a': 0.2,
    'update_min_d': 0.25, 'z_hit': 0.5, 'z_max': 0.05, 'z_rand': 0.5, 'z_short': 0.05,
    'always_reset_initial_pose': False, 'scan_topic': 'scan', 'map_topic': 'map',
    'first_map_only': False,
}
# upstream's covariance of the initial pose from parameters: 0.5 m and 0.26 rad (std)
INITIAL_COV = np.diag([0.5 * 0.5, 0.5 * 0.5, (math.pi / 12.0) ** 2])


def _yaw(q) -> float:
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def _pose_msg(x: float, y: float, yaw: float) -> Pose:
    pose = Pose()
    pose.position.x, pose.position.y = float(x), float(y)
    pose.orientation.z, pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return pose


class AmclNode(LifecycleNode):
    def __init__(self) -> None:
        super().__init__('amcl')
        self.get_logger().info('Creating')
        self.params = {name: declare_checked(self, name, default)
                       for name, default in PARAMETERS.items()}
        warn_unknown_parameters(self)
        self.core: AmclCore | None = None
        self._handles: list = []
        self._pose_pub = self._cloud_pub = None
        self._latest_tf: TransformStamped | None = None
        self._map_received = False

    def on_configure(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Configuring')
        self.params = {name: self.get_parameter(name).value for name in PARAMETERS}
        try:
            self.core = AmclCore(self.params)
        except ValueError as error:
            self.get_logger().error(str(error))
            return TransitionCallbackReturn.FAILURE
        self.tf_buffer = Buffer()
        # On a thread of its own, as upstream's listener: the scan callback waits for the
        # odometry at the scan's stamp, which must keep arriving meanwhile (on the node's
        # own executor /tf starved behind the scans and the buffer stopped at 1.3 s).
        self.tf_listener = TransformListener(self.tf_buffer, self, spin_thread=True)
        self.tf_broadcaster = TransformBroadcaster(self)
        self._pose_pub = self.create_lifecycle_publisher(
            PoseWithCovarianceStamped, 'amcl_pose', LATCHED)
        self._cloud_pub = self.create_lifecycle_publisher(
            ParticleCloud, 'particle_cloud', qos_profile_sensor_data)
        self._handles = [
            self.create_subscription(OccupancyGrid, self.params['map_topic'],
                                     self._on_map, LATCHED),
            self.create_subscription(PoseWithCovarianceStamped, 'initialpose',
                                     self._on_initial_pose, 10),
            self.create_subscription(LaserScan, self.params['scan_topic'], self._on_scan,
                                     qos_profile_sensor_data),
            self.create_service(Empty, 'reinitialize_global_localization',
                                self._on_global_localization),
            self.create_service(Empty, 'request_nomotion_update', self._on_nomotion_update),
        ]
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Activating')
        result = super().on_activate(state)
        if self.params['set_initial_pose'] and self.core is not None:
            p = self.params
            self.core.initial_pose(np.array([p['initial_pose.x'], p['initial_pose.y'],
                                             p['initial_pose.yaw']]), INITIAL_COV)
        return result

    def release(self) -> None:
        listener = getattr(self, 'tf_listener', None)
        if listener is not None:  # its thread first, then its node
            listener._stop_spinning()
            listener.unregister()
            listener.node.destroy_node()
            self.tf_listener = None
        for handle in self._handles:
            if hasattr(handle, 'srv_type'):
                self.destroy_service(handle)
            else:
                self.destroy_subscription(handle)
        for publisher in (self._pose_pub, self._cloud_pub):
            if publisher is not None:
                self.destroy_lifecycle_publisher(publisher)
        self._handles, self._pose_pub, self._cloud_pub = [], None, None
        self.core, self._latest_tf, self._map_received = None, None, False

    def _on_map(self, msg: OccupancyGrid) -> None:
        if self.core is None or (self.params['first_map_only'] and self._map_received):
            return
        info = msg.info
        self.get_logger().info(
            f'Received a {info.width} X {info.height} map @ {info.resolution:.3f} m/pix')
        if msg.header.frame_id != self.params['global_frame_id']:
            self.get_logger().warning(
                f'Frame_id of map received:\'{msg.header.frame_id}\' doesn\'t match '
                f'global_frame_id:\'{self.params["global_frame_id"]}\'. This could cause '
                'issues with reading published topics')
        self.core.set_map(AmclMap.from_grid(
            np.asarray(msg.data, dtype=np.int8), info.width, info.height, info.resolution,
            info.origin.position.x, info.origin.position.y))
        self._map_received = True

    def _on_initial_pose(self, msg: PoseWithCovarianceStamped) -> None:
        if self.core is None:
            return
        if msg.header.frame_id != self.params['global_frame_id']:
            self.get_logger().warning(
                f'Ignoring initial pose in frame "{msg.header.frame_id}"; initial poses '
                f'must be in the global frame, "{self.params["global_frame_id"]}"')
            return
        p = msg.pose.pose
        yaw = _yaw(p.orientation)
        now = self.get_clock().now().nanoseconds / 1e9
        self.get_logger().info(f'initialPoseReceived: setting pose ({now:.6f}): '
                               f'{p.position.x:.3f} {p.position.y:.3f} {yaw:.3f}')
        c = msg.pose.covariance
        cov = np.array([[c[0], c[1], 0.0], [c[6], c[7], 0.0], [0.0, 0.0, c[35]]])
        self.core.initial_pose(np.array([p.position.x, p.position.y, yaw]), cov)

    def _on_global_localization(self, request: Empty.Request, response: Empty.Response
                                ) -> Empty.Response:
        if self.core is not None and self.core.map is not None:
            self.get_logger().info('Initializing with uniform distribution')
            try:
                self.core.global_localization()
            except ValueError as error:
                self.get_logger().error(str(error))
                return response
            self.get_logger().info('Global initialisation done!')
        return response

    def _on_nomotion_update(self, request: Empty.Request, response: Empty.Response
                            ) -> Empty.Response:
        if self.core is not None:
            self.core.nomotion_update()
            self.get_logger().info('Requesting no-motion update')
        return response

    def _lookup(self, target: str, source: str, stamp: Time) -> TransformStamped | None:
        try:
            return self.tf_buffer.lookup_transform(target, source, stamp,
                                                   Duration(seconds=0.1))
        except Exception as error:  # tf2's lookup errors: no transform yet
            self.get_logger().warning(f'Failed to compute odom pose: {error}',
                                      throttle_duration_sec=5.0)
            return None

    def _on_scan(self, msg: LaserScan) -> None:
        core = self.core
        if core is None or not self.is_active() or core.map is None:
            return
        stamp = Time.from_msg(msg.header.stamp)
        odom_tf = self._lookup(self.params['odom_frame_id'], self.params['base_frame_id'],
                               stamp)
        laser_tf = self._lookup(self.params['base_frame_id'], msg.header.frame_id, Time())
        if odom_tf is None or laser_tf is None:
            return
        t = odom_tf.transform
        odom_pose = np.array([t.translation.x, t.translation.y, _yaw(t.rotation)])
        lt = laser_tf.transform
        laser_yaw = _yaw(lt.rotation)
        data = laser_data(np.asarray(msg.ranges, dtype=np.float64),
                          msg.angle_min + laser_yaw, msg.angle_increment, msg.range_min,
                          msg.range_max, core.laser_params)
        laser_pose = np.array([lt.translation.x, lt.translation.y, 0.0])
        updated_before = core.resample_count
        try:
            estimate = core.laser_received(odom_pose, data, laser_pose)
        except ValueError as error:  # e.g. a map without free cells for recovery particles
            self.get_logger().error(str(error), throttle_duration_sec=5.0)
            return
        if core.resample_count != updated_before or estimate is not None:
            self._publish_cloud(msg.header.stamp)
        if estimate is not None:
            self._publish_estimate(estimate, msg.header.stamp, odom_pose)
        elif self._latest_tf is not None:
            self._send_tf(self._latest_tf, stamp)

    def _publish_cloud(self, stamp) -> None:
        cloud = ParticleCloud()
        cloud.header.frame_id = self.params['global_frame_id']
        cloud.header.stamp = stamp
        poses, weights = self.core.pf.poses, self.core.pf.weights
        cloud.particles = [Particle(pose=_pose_msg(*pose), weight=float(weight))
                           for pose, weight in zip(poses, weights, strict=True)]
        self._cloud_pub.publish(cloud)

    def _publish_estimate(self, estimate: Estimate, stamp, odom_pose: np.ndarray) -> None:
        x, y, yaw = (float(v) for v in estimate.pose)
        msg = PoseWithCovarianceStamped()
        msg.header.frame_id = self.params['global_frame_id']
        msg.header.stamp = stamp
        msg.pose.pose = _pose_msg(x, y, yaw)
        cov = [0.0] * 36
        cov[0], cov[1] = estimate.cov[0, 0], estimate.cov[0, 1]
        cov[6], cov[7] = estimate.cov[1, 0], estimate.cov[1, 1]
        cov[35] = estimate.cov[2, 2]
        msg.pose.covariance = [float(v) for v in cov]
        self._pose_pub.publish(msg)
        # map -> odom = (map -> base) * inverse(odom -> base)
        ox, oy, oyaw = odom_pose
        tyaw = yaw - oyaw
        tx = x - (ox * math.cos(tyaw) - oy * math.sin(tyaw))
        ty = y - (ox * math.sin(tyaw) + oy * math.cos(tyaw))
        transform = TransformStamped()
        transform.header.frame_id = self.params['global_frame_id']
        transform.child_frame_id = self.params['odom_frame_id']
        transform.transform.translation.x, transform.transform.translation.y = tx, ty
        transform.transform.rotation.z = math.sin(tyaw / 2)
        transform.transform.rotation.w = math.cos(tyaw / 2)
        self._latest_tf = transform
        self._send_tf(transform, Time.from_msg(stamp))

    def _send_tf(self, transform: TransformStamped, stamp: Time) -> None:
        if not self.params['tf_broadcast']:
            return
        tolerance = Duration(seconds=self.params['transform_tolerance'])
        transform.header.stamp = (stamp + tolerance).to_msg()
        self.tf_broadcaster.sendTransform(transform)


def main(args: list[str] | None = None) -> int:
    return run_server(AmclNode, args)


if __name__ == '__main__':
    sys.exit(main())
