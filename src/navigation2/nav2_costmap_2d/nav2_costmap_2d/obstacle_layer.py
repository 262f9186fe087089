"""ObstacleLayer: laser scans mark their endpoints lethal and clear the cells rays cross.

Parameters as upstream, per layer (`observation_sources`, `combination_method`,
`footprint_clearing_enabled`, ...) and per source (`topic`, `marking`, `clearing`,
`obstacle_max_range` 2.5, `obstacle_min_range` 0.0, `raytrace_max_range` 3.0,
`raytrace_min_range` 0.0, `observation_persistence`, `inf_is_valid`, ...). Heights
(`min_obstacle_height`, `max_obstacle_height`) are read and ignored: scans are 2-D here, which is
also how a `voxel_layer` entry of a Nav2 params file is run (as this 2-D layer).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from nav2_costmap_2d.cost_values import FREE_SPACE, LETHAL_OBSTACLE, NO_INFORMATION
from nav2_costmap_2d.costmap_2d import Costmap2D
from nav2_costmap_2d.costmap_layer import CostmapLayer, ParameterError, read_parameter
from nav2_costmap_2d.footprint import transform_footprint
from nav2_costmap_2d.raytrace import raytrace_cells

COMBINATION_METHODS = {0: 'Overwrite', 1: 'Max', 2: 'MaxWithoutUnknownOverwrite'}


@dataclass
class ObservationSource:
    """One entry of `observation_sources` with upstream's defaults."""

    name: str
    topic: str
    sensor_frame: str = ''
    observation_persistence: float = 0.0
    expected_update_rate: float = 0.0
    data_type: str = 'LaserScan'
    min_obstacle_height: float = 0.0
    max_obstacle_height: float = 0.0
    inf_is_valid: bool = False
    marking: bool = True
    clearing: bool = False
    obstacle_max_range: float = 2.5
    obstacle_min_range: float = 0.0
    raytrace_max_range: float = 3.0
    raytrace_min_range: float = 0.0
    observations: list[tuple[float, Observation]] = field(default_factory=list)

    @classmethod
    def from_params(cls, layer: str, name: str, params: Mapping[str, Any]) -> ObservationSource:
        source = cls(name, topic=name)
        prefix = f'{layer}.{name}'
        for key in ('topic', 'sensor_frame', 'observation_persistence', 'expected_update_rate',
                    'data_type', 'min_obstacle_height', 'max_obstacle_height', 'inf_is_valid',
                    'marking', 'clearing', 'obstacle_max_range', 'obstacle_min_range',
                    'raytrace_max_range', 'raytrace_min_range'):
            setattr(source, key, read_parameter(params, prefix, key, getattr(source, key)))
        if source.data_type not in ('LaserScan', 'PointCloud2'):
            raise ParameterError(
                f'{prefix}.data_type: Only topics that use point cloud2s or laser scans are '
                f'currently supported, got {source.data_type!r}')
        return source

    def add(self, stamp: float, observation: Observation) -> None:
        """Keep the newest, and the older ones within observation_persistence seconds."""
        self.observations.append((stamp, observation))
        newest = max(s for s, _ in self.observations)
        if self.observation_persistence == 0:
            self.observations = [(s, o) for s, o in self.observations if s == newest][-1:]
        else:
            self.observations = [(s, o) for s, o in self.observations
                                 if newest - s <= self.observation_persistence]


@dataclass
class Observation:
    """Points in the costmap's frame seen from a sensor origin, with the source's ranges."""

    origin: tuple[float, float]
    points: np.ndarray  # (N, 2)
    obstacle_max_range: float = 2.5
    obstacle_min_range: float = 0.0
    raytrace_max_range: float = 3.0
    raytrace_min_range: float = 0.0


def scan_to_points(ranges: Sequence[float], angle_min: float, angle_increment: float,
                   range_min: float, range_max: float, sensor_pose: tuple[float, float, float],
                   inf_is_valid: bool = False) -> np.ndarray:
    """laser_geometry's projection in 2-D: readings in [range_min, range_max) become points."""
    r = np.asarray(ranges, dtype=np.float64)
    if inf_is_valid:
        # upstream turns +inf into range_max - 0.1 mm, so the ray clears but marks nothing
        r = np.where(np.isposinf(r), range_max - 0.0001, r)
    angles = angle_min + angle_increment * np.arange(r.size)
    valid = np.isfinite(r) & (r >= range_min) & (r < range_max)
    x, y, yaw = sensor_pose
    theta = angles[valid] + yaw
    return np.column_stack((x + r[valid] * np.cos(theta), y + r[valid] * np.sin(theta)))


class ObstacleLayer(CostmapLayer):
    """nav2_costmap_2d::ObstacleLayer for 2-D scans."""

    def __init__(self, name: str, layered_costmap: Any, params: Mapping[str, Any] | None = None,
                 node_params: Mapping[str, Any] | None = None) -> None:
        node = dict(node_params or {})
        track_unknown = read_parameter(node, 'costmap', 'track_unknown_space', False)
        default = NO_INFORMATION if track_unknown else FREE_SPACE
        super().__init__(name, layered_costmap, params, default_value=default)
        self.footprint_clearing_enabled: bool = self.parameter('footprint_clearing_enabled', True)
        self.min_obstacle_height: float = self.parameter('min_obstacle_height', 0.0)
        self.max_obstacle_height: float = self.parameter('max_obstacle_height', 2.0)
        method = self.parameter('combination_method', 1)
        self.warnings: list[str] = []
        if method not in COMBINATION_METHODS:
            self.warnings.append(
                f'Param combination_method: {method}. Possible values are  0 (Overwrite) or 1 '
                "(Maximum) or 2 (Maximum without overwriting the master's NO_INFORMATION "
                'values).The default value 1 will be used')
            method = 1
        self.combination_method: int = method
        topics: str = self.parameter('observation_sources', '')
        self.sources = {source: ObservationSource.from_params(
            name, source, self.params.get(source) or {}) for source in topics.split()}
        self._transformed_footprint: list[tuple[float, float]] = []

    # --- data in -------------------------------------------------------------------------
    def add_scan(self, source: str, ranges: Sequence[float], angle_min: float,
                 angle_increment: float, range_min: float, range_max: float,
                 sensor_pose: tuple[float, float, float], stamp: float = 0.0) -> None:
        """A LaserScan of `source`, its sensor at sensor_pose in the costmap's frame."""
        spec = self.sources[source]
        points = scan_to_points(ranges, angle_min, angle_increment, range_min, range_max,
                                sensor_pose, spec.inf_is_valid)
        self.add_points(source, points, sensor_pose[:2], stamp)

    def add_points(self, source: str, points: np.ndarray, origin: tuple[float, float],
                   stamp: float = 0.0) -> None:
        spec = self.sources[source]
        points = np.asarray(points, dtype=np.float64).reshape(-1, 2)
        spec.add(stamp, Observation(
            (float(origin[0]), float(origin[1])), points,
            spec.obstacle_max_range, spec.obstacle_min_range, spec.raytrace_max_range,
            spec.raytrace_min_range))

    def observations(self, marking: bool) -> list[Observation]:
        return [observation for spec in self.sources.values()
                if (spec.marking if marking else spec.clearing)
                for _, observation in spec.observations]

    # --- the update ----------------------------------------------------------------------
    def update_bounds(self, robot_x: float, robot_y: float, robot_yaw: float) -> None:
        if self.layered_costmap.is_rolling():
            self.update_origin(robot_x - self.size_in_meters_x / 2,
                               robot_y - self.size_in_meters_y / 2)
        if not self.enabled:
            return
        for observation in self.observations(marking=False):
            self.raytrace_freespace(observation)
        for observation in self.observations(marking=True):
            self.mark(observation)
        if self.footprint_clearing_enabled:
            self._transformed_footprint = transform_footprint(
                robot_x, robot_y, robot_yaw, self.layered_costmap.footprint)

    def mark(self, observation: Observation) -> None:
        """Endpoints within [obstacle_min_range, obstacle_max_range] become LETHAL_OBSTACLE."""
        origin = self.world_to_map(*observation.origin)
        if origin is None or observation.points.size == 0:
            return  # upstream: "Sensor origin is out of map bounds"
        px, py = observation.points[:, 0], observation.points[:, 1]
        mx, my, inside = self.world_to_map_array(px, py)
        dist_sq = (px - observation.origin[0]) ** 2 + (py - observation.origin[1]) ** 2
        keep = (inside & (dist_sq <= observation.obstacle_max_range ** 2)
                & (dist_sq >= observation.obstacle_min_range ** 2))
        cells = np.hypot(mx - origin[0], my - origin[1]).astype(np.int64)
        keep &= (cells <= self.cell_distance(observation.obstacle_max_range))
        keep &= (cells >= self.cell_distance(observation.obstacle_min_range))
        self.costmap[my[keep], mx[keep]] = LETHAL_OBSTACLE

    def raytrace_freespace(self, observation: Observation) -> None:
        """Clear the cells between the sensor and each point, within the raytrace ranges."""
        ox, oy = observation.origin
        origin = self.world_to_map(ox, oy)
        if origin is None or observation.points.size == 0:
            return
        wx = observation.points[:, 0].copy()
        wy = observation.points[:, 1].copy()
        a, b = wx - ox, wy - oy
        end_x = self.origin_x + self.size_x * self.resolution
        end_y = self.origin_y + self.size_y * self.resolution
        with np.errstate(divide='ignore', invalid='ignore'):
            # rays leaving the map are cut at its edge, as upstream does
            low = wx < self.origin_x
            t = (self.origin_x - ox) / a
            wx, wy = np.where(low, self.origin_x, wx), np.where(low, oy + b * t, wy)
            low = wy < self.origin_y
            t = (self.origin_y - oy) / b
            wx, wy = np.where(low, ox + a * t, wx), np.where(low, self.origin_y, wy)
            high = wx > end_x
            t = (end_x - ox) / a
            wx, wy = np.where(high, end_x - 0.001, wx), np.where(high, oy + b * t, wy)
            high = wy > end_y
            t = (end_y - oy) / b
            wx, wy = np.where(high, ox + a * t, wx), np.where(high, end_y - 0.001, wy)
        mx, my, inside = self.world_to_map_array(wx, wy)
        xs, ys = raytrace_cells(origin[0], origin[1], mx[inside], my[inside],
                                self.cell_distance(observation.raytrace_max_range),
                                self.cell_distance(observation.raytrace_min_range))
        ok = (xs >= 0) & (ys >= 0) & (xs < self.size_x) & (ys < self.size_y)
        self.costmap[ys[ok], xs[ok]] = FREE_SPACE

    def update_costs(self, master: Costmap2D) -> None:
        if not self.enabled:
            return
        if self.footprint_clearing_enabled and self._transformed_footprint:
            self.set_convex_polygon_cost(self._transformed_footprint, FREE_SPACE)
        if self.combination_method == 0:
            self.update_with_overwrite(master)
        elif self.combination_method == 2:
            self.update_with_max_without_unknown_overwrite(master)
        else:
            self.update_with_max(master)
        self.current = True  # current again after a reset once it is layered in

    def reset(self) -> None:
        super().reset()
        for spec in self.sources.values():
            spec.observations.clear()

    def is_clearable(self) -> bool:
        return True

