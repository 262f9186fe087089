"""`ros2 run nav2_collision_monitor collision_monitor`: Nav2's collision monitor.

A lifecycle node between the velocity smoother and the robot: every command on
cmd_vel_in_topic (`cmd_vel_smoothed`) is checked against the observation sources' points
inside the `polygons` and published on cmd_vel_out_topic (`cmd_vel`) unchanged, stopped,
slowed down, limited, or - for an `approach` shape such as the robot's footprint - scaled so
that the robot would need at least time_before_collision to reach an obstacle. A source whose
data is older than source_timeout stops the robot. Zero commands are published for
stop_pub_timeout after a stop, then nothing until the next command.
"""

from __future__ import annotations

import math
import sys
from typing import Any

import numpy as np
from geometry_msgs.msg import Point32, PolygonStamped, Twist, TwistStamped
from nav2_msgs.msg import CollisionMonitorState
from nav2_util.lifecycle_node import LifecycleNode, run_server
from nav2_util.parameters import declare_checked, warn_unknown_parameters
from rclpy.duration import Duration
from rclpy.lifecycle import State, TransitionCallbackReturn
from rclpy.parameter import Parameter
from rclpy.qos import DurabilityPolicy, QoSProfile, qos_profile_sensor_data
from rclpy.time import Time
from sensor_msgs.msg import LaserScan
from tf2_ros import Buffer, TransformListener

from nav2_collision_monitor import geometry
from nav2_collision_monitor.shapes import ScanSource, Shape, read_shape

DO_NOTHING, STOP, SLOWDOWN, APPROACH, LIMIT = 0, 1, 2, 3, 4
INVALID_SOURCE = 'invalid source'


class CollisionMonitor(LifecycleNode):
    def __init__(self) -> None:
        super().__init__('collision_monitor')
        self.get_logger().info('Creating')
        self.cmd_vel_in_topic = declare_checked(self, 'cmd_vel_in_topic', 'cmd_vel_smoothed')
        self.cmd_vel_out_topic = declare_checked(self, 'cmd_vel_out_topic', 'cmd_vel')
        self.state_topic = declare_checked(self, 'state_topic', '')
        self.base_frame = declare_checked(self, 'base_frame_id', 'base_footprint')
        self.odom_frame = declare_checked(self, 'odom_frame_id', 'odom')
        self.transform_tolerance = declare_checked(self, 'transform_tolerance', 0.1)
        self.source_timeout = declare_checked(self, 'source_timeout', 2.0)
        self.base_shift_correction = declare_checked(self, 'base_shift_correction', True)
        self.stop_pub_timeout = declare_checked(self, 'stop_pub_timeout', 1.0)
        self.stamped = declare_checked(self, 'enable_stamped_cmd_vel', False)
        declare_checked(self, 'use_realtime_priority', False)
        self.polygon_names = declare_checked(self, 'polygons', Parameter.Type.STRING_ARRAY) or []
        self.source_names = declare_checked(
            self, 'observation_sources', Parameter.Type.STRING_ARRAY) or []
        self.shapes: list[Shape] = []
        self.sources: list[ScanSource] = []
        self._config_error = ''
        try:
            for name in self.source_names:
                kind = declare_checked(self, f'{name}.type', 'scan')
                if kind != 'scan':
                    raise ValueError(f'[{name}]: Unknown source type: {kind} (only scan '
                                     'sources are built here)')
                self.sources.append(ScanSource(self, name, self.source_timeout))
            self.shapes = [read_shape(self, name, self.source_names)
                           for name in self.polygon_names]
        except ValueError as error:
            self._config_error = str(error)
        warn_unknown_parameters(self)
        self._handles: list[Any] = []
        self._pubs: list[Any] = []
        self._polygon_pubs: dict[str, Any] = {}
        self._out_pub = self._state_pub = None
        self.tf_buffer: Buffer | None = None
        self._tf_listener: TransformListener | None = None
        self.active = False
        self.prev_action: tuple[int, str, geometry.Velocity] = (DO_NOTHING, '', (0., 0., 0.))
        self.stop_stamp = self.get_clock().now()

    # --- lifecycle -----------------------------------------------------------------------
    def on_configure(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Configuring')
        if self._config_error:
            self.get_logger().error(f'Error while getting parameters: {self._config_error}')
            return TransitionCallbackReturn.FAILURE
        if not self.shapes and not self.polygon_names:
            self.get_logger().error("Error while getting parameters: 'polygons' is not set")
            return TransitionCallbackReturn.FAILURE
        self.tf_buffer = Buffer(node=self)
        self._tf_listener = TransformListener(self.tf_buffer, self, spin_thread=True)
        twist = TwistStamped if self.stamped else Twist
        self._out_pub = self.create_lifecycle_publisher(twist, self.cmd_vel_out_topic, 1)
        self._pubs = [self._out_pub]
        if self.state_topic:
            self._state_pub = self.create_lifecycle_publisher(
                CollisionMonitorState, self.state_topic, 1)
            self._pubs.append(self._state_pub)
        latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        for shape in self.shapes:
            if shape.visualize:
                pub = self.create_lifecycle_publisher(PolygonStamped, shape.polygon_pub_topic,
                                                      latched)
                self._polygon_pubs[shape.name] = pub
                self._pubs.append(pub)
        self._handles = [self.create_subscription(twist, self.cmd_vel_in_topic,
                                                  self.on_cmd_vel_in, 1)]
        for source in self.sources:
            self._handles.append(self.create_subscription(
                LaserScan, source.topic, source.on_scan, qos_profile_sensor_data))
        for shape in self.shapes:
            if shape.footprint_topic:
                self._handles.append(self.create_subscription(
                    PolygonStamped, shape.footprint_topic,
                    lambda msg, shape=shape: self.on_footprint(shape, msg), 1))
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Activating')
        result = super().on_activate(state)
        self.active = True
        return result

    def on_deactivate(self, state: State) -> TransitionCallbackReturn:
        self.active = False
        return super().on_deactivate(state)

    def release(self) -> None:
        self.active = False
        for handle in self._handles:
            self.destroy_subscription(handle)
        for pub in self._pubs:
            self.destroy_lifecycle_publisher(pub)
        if self._tf_listener is not None:
            self._tf_listener.unregister()
        self._handles, self._pubs, self._polygon_pubs = [], [], {}
        self._out_pub = self._state_pub = self._tf_listener = self.tf_buffer = None

    # --- inputs --------------------------------------------------------------------------
    def on_footprint(self, shape: Shape, msg: PolygonStamped) -> None:
        """The costmap's footprint (in its global frame) moved into the base frame."""
        if self.tf_buffer is None or len(msg.polygon.points) < 3:
            return
        points = [(p.x, p.y) for p in msg.polygon.points]
        frame = msg.header.frame_id or self.base_frame
        if frame != self.base_frame:
            try:
                t = self.tf_buffer.lookup_transform(self.base_frame, frame, Time())
            except Exception:  # no transform yet: keep the shape unset or as it was
                return
            tr = t.transform
            q = tr.rotation
            yaw = math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))
            shape.vertices = geometry.transform_points(points, tr.translation.x,
                                                       tr.translation.y, yaw)
        else:
            shape.vertices = np.asarray(points, dtype=float)

    def on_cmd_vel_in(self, msg: Any) -> None:
        twist = msg.twist if isinstance(msg, TwistStamped) else msg
        values = (twist.linear.x, twist.linear.y, twist.angular.z,
                  twist.linear.z, twist.angular.x, twist.angular.y)
        if not all(math.isfinite(v) for v in values):
            self.get_logger().error('Velocity message contains NaNs or Infs! Ignoring as invalid!')
            return
        header = msg.header if isinstance(msg, TwistStamped) else None
        self.process((twist.linear.x, twist.linear.y, twist.angular.z), header)

    # --- the monitor ---------------------------------------------------------------------
    def process(self, cmd_vel_in: geometry.Velocity, header: Any) -> None:
        if not self.active or self.tf_buffer is None:
            return
        now = self.get_clock().now()
        action, polygon, req_vel = DO_NOTHING, '', cmd_vel_in
        acting: Shape | None = None
        points: dict[str, np.ndarray] = {}
        for source in self.sources:
            points[source.name] = np.zeros((0, 2))
            if not source.enabled:
                continue
            data = source.points(now, self.tf_buffer, self.base_frame, self.odom_frame,
                                 self.base_shift_correction, self.transform_tolerance)
            if data is None and source.source_timeout != 0.0:
                action, polygon, req_vel = STOP, INVALID_SOURCE, (0.0, 0.0, 0.0)
                break
            if data is not None:
                points[source.name] = data
        for shape in self.shapes:
            if not shape.enabled:
                continue
            if action == STOP:
                break
            if not shape.is_shape_set():
                continue
            chosen = [points[name] for name in shape.sources_names if name in points]
            cloud = np.concatenate(chosen) if chosen else np.zeros((0, 2))
            result = self._shape_action(shape, cloud, cmd_vel_in, req_vel)
            if result is not None:
                action, req_vel = result
                polygon, acting = shape.name, shape
        if polygon != self.prev_action[1]:
            self._notify(action, polygon, acting)
        self._publish_velocity(req_vel, header, now)
        self._publish_polygons(now)
        self.prev_action = (action, polygon, req_vel)

    def _shape_action(self, shape: Shape, cloud: np.ndarray, velocity: geometry.Velocity,
                      req_vel: geometry.Velocity) -> tuple[int, geometry.Velocity] | None:
        """The shape's (action, safe velocity) if it is more restrictive than req_vel."""
        if shape.action_type == 'approach':
            t = geometry.collision_time(cloud, shape.count_inside, velocity,
                                        shape.time_before_collision,
                                        shape.simulation_time_step, shape.min_points)
            if t < 0.0:
                return None
            safe = geometry.scale(velocity, t / shape.time_before_collision)
            return (APPROACH, safe) if geometry.is_less(safe, req_vel) else None
        if shape.count_inside(cloud) < shape.min_points:
            return None
        if shape.action_type == 'stop':
            return STOP, (0.0, 0.0, 0.0)
        if shape.action_type == 'slowdown':
            safe = geometry.scale(velocity, shape.slowdown_ratio)
            return (SLOWDOWN, safe) if geometry.is_less(safe, req_vel) else None
        ratio = 1.0
        linear = math.hypot(velocity[0], velocity[1])
        if linear != 0.0:
            ratio = min(ratio, shape.linear_limit / linear)
        if velocity[2] != 0.0:
            ratio = min(ratio, shape.angular_limit / abs(velocity[2]))
        safe = geometry.scale(velocity, min(max(ratio, 0.0), 1.0))
        return (LIMIT, safe) if geometry.is_less(safe, req_vel) else None

    def _notify(self, action: int, polygon: str, shape: Shape | None) -> None:
        log = self.get_logger()
        if action == STOP and polygon == INVALID_SOURCE:
            log.warning('Robot to stop due to invalid source. Either due to data not published '
                        'yet, or to lack of new data received within the sensor timeout, or if '
                        'impossible to transform data to base frame')
        elif action == STOP:
            log.info(f'Robot to stop due to {polygon} polygon')
        elif action == SLOWDOWN:
            log.info(f'Robot to slowdown for {shape.slowdown_ratio * 100:f} percents due to '
                     f'{polygon} polygon')
        elif action == LIMIT:
            log.info(f'Robot to limit speed due to {polygon} polygon')
        elif action == APPROACH:
            log.info(f'Robot to approach for {shape.time_before_collision:f} seconds away from '
                     'collision')
        else:
            log.info('Robot to continue normal operation')
        if self._state_pub is not None:
            self._state_pub.publish(CollisionMonitorState(action_type=action,
                                                          polygon_name=polygon))

    def _publish_velocity(self, vel: geometry.Velocity, header: Any, now: Time) -> None:
        if vel == (0.0, 0.0, 0.0):
            if self.prev_action[2] != (0.0, 0.0, 0.0):
                self.stop_stamp = now
            elif now - self.stop_stamp > Duration(seconds=self.stop_pub_timeout):
                return  # stopped long enough: leave the robot's driver alone
        twist = Twist()
        twist.linear.x, twist.linear.y, twist.angular.z = (float(v) for v in vel)
        if self.stamped:
            msg = TwistStamped(twist=twist)
            if header is not None:
                msg.header = header
            self._out_pub.publish(msg)
        else:
            self._out_pub.publish(twist)

    def _publish_polygons(self, now: Time) -> None:
        for shape in self.shapes:
            pub = self._polygon_pubs.get(shape.name)
            if pub is None or not shape.is_shape_set():
                continue
            msg = PolygonStamped()
            msg.header.frame_id = self.base_frame
            msg.header.stamp = now.to_msg()
            msg.polygon.points = [Point32(x=float(x), y=float(y)) for x, y in shape.outline()]
            pub.publish(msg)


def main(args: list[str] | None = None) -> int:
    return run_server(CollisionMonitor, args)


if __name__ == '__main__':
    sys.exit(main())
