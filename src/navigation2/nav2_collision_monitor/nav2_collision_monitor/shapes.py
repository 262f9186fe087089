"""The collision monitor's polygons and data sources, read from the node's parameters."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from nav2_util.parameters import declare_checked
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.time import Time

from nav2_collision_monitor import geometry

ACTION_TYPES = {'stop': 1, 'slowdown': 2, 'approach': 3, 'limit': 4}
SHAPE_TYPES = ('polygon', 'circle')


def _yaw(q: Any) -> float:
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


@dataclass
class Shape:
    """One entry of `polygons`: a polygon or circle around the robot and what it does."""

    name: str
    kind: str
    action_type: str
    enabled: bool = True
    min_points: int = 4
    slowdown_ratio: float = 0.5
    linear_limit: float = 0.5
    angular_limit: float = 0.5
    time_before_collision: float = 2.0
    simulation_time_step: float = 0.1
    visualize: bool = False
    polygon_pub_topic: str = ''
    footprint_topic: str = ''
    sources_names: list[str] = field(default_factory=list)
    vertices: np.ndarray | None = None  # base frame; None until a footprint arrives
    radius: float = 0.0

    @property
    def action_id(self) -> int:
        return ACTION_TYPES[self.action_type]

    def is_shape_set(self) -> bool:
        return self.kind == 'circle' or self.vertices is not None

    def count_inside(self, points: np.ndarray) -> int:
        if self.kind == 'circle':
            return geometry.points_in_circle(points, self.radius)
        return geometry.points_in_polygon(points, self.vertices)

    def outline(self) -> np.ndarray:
        if self.kind == 'circle':
            return geometry.circle_vertices(self.radius)
        return self.vertices if self.vertices is not None else np.zeros((0, 2))


def read_shape(node: Node, name: str, source_names: list[str]) -> Shape:
    """The parameters `<name>.*` as upstream's Polygon/Circle declare them; ValueError if bad."""
    kind = declare_checked(node, f'{name}.type', Parameter.Type.STRING)
    if kind not in SHAPE_TYPES:
        raise ValueError(f'[{name}]: Unknown polygon type: {kind} (allowed: polygon, circle)')
    action = declare_checked(node, f'{name}.action_type', Parameter.Type.STRING)
    if action not in ACTION_TYPES:
        raise ValueError(f'[{name}]: Unknown action type: {action} (allowed: '
                         f"{', '.join(ACTION_TYPES)})")
    shape = Shape(name, kind, action)
    shape.enabled = declare_checked(node, f'{name}.enabled', True)
    shape.min_points = declare_checked(node, f'{name}.min_points', 4)
    if action == 'slowdown':
        shape.slowdown_ratio = declare_checked(node, f'{name}.slowdown_ratio', 0.5)
    elif action == 'limit':
        shape.linear_limit = declare_checked(node, f'{name}.linear_limit', 0.5)
        shape.angular_limit = declare_checked(node, f'{name}.angular_limit', 0.5)
    elif action == 'approach':
        shape.time_before_collision = declare_checked(
            node, f'{name}.time_before_collision', 2.0)
        shape.simulation_time_step = declare_checked(
            node, f'{name}.simulation_time_step', 0.1)
        if not shape.simulation_time_step > 0.0:
            raise ValueError(f'[{name}]: simulation_time_step must be greater than 0.0')
    shape.visualize = declare_checked(node, f'{name}.visualize', False)
    if shape.visualize:
        shape.polygon_pub_topic = declare_checked(node, f'{name}.polygon_pub_topic', name)
    declare_checked(node, f'{name}.polygon_subscribe_transient_local', False)
    shape.sources_names = declare_checked(node, f'{name}.sources_names', list(source_names))
    if kind == 'circle':
        shape.radius = declare_checked(node, f'{name}.radius', Parameter.Type.DOUBLE)
        if shape.radius is None or not shape.radius > 0.0:
            raise ValueError(f'[{name}]: radius must be set and greater than 0.0')
        return shape
    if action == 'approach':
        shape.footprint_topic = declare_checked(
            node, f'{name}.footprint_topic', 'local_costmap/published_footprint')
    points = declare_checked(node, f'{name}.points', Parameter.Type.STRING)
    if points:
        shape.footprint_topic = ''
        shape.vertices = geometry.parse_points(points)
    elif not shape.footprint_topic:
        raise ValueError(f'[{name}]: Error while getting polygon parameters: neither points '
                         'nor footprint_topic is set')
    return shape


class ScanSource:
    """An `observation_sources` entry of type scan: the latest LaserScan as base-frame points."""

    def __init__(self, node: Node, name: str, source_timeout: float) -> None:
        self.name = name
        self.topic = declare_checked(node, f'{name}.topic', 'scan')
        self.enabled = declare_checked(node, f'{name}.enabled', True)
        self.source_timeout = declare_checked(node, f'{name}.source_timeout', source_timeout)
        # pointcloud sources' keys, accepted for a scan as upstream's params file gives them
        declare_checked(node, f'{name}.min_height', 0.05)
        declare_checked(node, f'{name}.max_height', 0.5)
        self.scan: Any = None
        self._logger = node.get_logger()

    def on_scan(self, msg: Any) -> None:
        self.scan = msg

    def points(self, now: Time, tf_buffer: Any, base_frame: str, odom_frame: str,
               base_shift_correction: bool, tolerance: float) -> np.ndarray | None:
        """The scan's points in the base frame, or None when the source is invalid."""
        scan = self.scan
        if scan is None:
            return None
        stamp = Time.from_msg(scan.header.stamp, clock_type=now.clock_type)
        age = (now - stamp).nanoseconds * 1e-9
        if self.source_timeout != 0.0 and age > self.source_timeout:
            self._logger.warning(
                f'[{self.name}]: Latest source and current collision monitor node timestamps '
                f'differ on {age:f} seconds. Ignoring the source.')
            return None
        # No waiting for TF here: this runs in the command callback, and a wait would hold
        # the scans back (upstream waits up to transform_tolerance on its own thread).
        try:
            if base_shift_correction:
                t = tf_buffer.lookup_transform_full(
                    base_frame, now, scan.header.frame_id, stamp, odom_frame)
            else:
                t = tf_buffer.lookup_transform(base_frame, scan.header.frame_id, Time())
        except Exception:  # odom not yet at `now`: the lidar is fixed on the robot, so
            try:  # its latest transform holds
                t = tf_buffer.lookup_transform(base_frame, scan.header.frame_id, Time())
            except Exception:  # no transform at all: the source is invalid, as upstream
                return None
        ranges = np.asarray(scan.ranges, dtype=float)
        angles = scan.angle_min + scan.angle_increment * np.arange(len(ranges))
        keep = np.isfinite(ranges) & (ranges >= scan.range_min) & (ranges <= scan.range_max)
        local = np.stack([ranges[keep] * np.cos(angles[keep]),
                          ranges[keep] * np.sin(angles[keep])], axis=1)
        tr = t.transform
        return geometry.transform_points(local, tr.translation.x, tr.translation.y,
                                         _yaw(tr.rotation))
