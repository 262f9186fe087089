"""nav2_costmap_2d's CostmapSubscriber, FootprintSubscriber and CostmapTopicCollisionChecker:
collision checking against a costmap another node publishes (behavior_server's view of the
local costmap, as upstream's).

- `<topic>` (nav2_msgs/Costmap, transient local, reliable, depth 1) and `<topic>_updates`
  (nav2_msgs/CostmapUpdate, depth 10) give the grid;
- the footprint topic (geometry_msgs/PolygonStamped, system default QoS) gives the robot's
  outline in the costmap's frame, moved into the robot's frame with TF at its stamp.
A pose is free when the footprint's outline there costs less than LETHAL_OBSTACLE; no
costmap, no footprint or a pose off the grid: one error line under the server's name, and
the pose is not free (the behaviour then ends with COLLISION_AHEAD, as upstream's).
"""

from __future__ import annotations

import threading
from typing import Any

import numpy as np
from geometry_msgs.msg import PolygonStamped
from nav2_msgs.msg import Costmap, CostmapUpdate
from rclpy.duration import Duration
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy, qos_profile_system_default
from rclpy.time import Time
from tf2_ros import Buffer, TransformException

from nav2_behaviors.motion import (
    LETHAL_OBSTACLE,
    Point,
    Pose2D,
    footprint_cost,
    footprint_to_robot_frame,
    transform_footprint,
    world_to_map,
    yaw_of,
)

COSTMAP_QOS = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                         reliability=ReliabilityPolicy.RELIABLE)
UPDATES_QOS = QoSProfile(depth=10, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                         reliability=ReliabilityPolicy.RELIABLE)


class CollisionCheckerException(RuntimeError):
    pass


class CostmapSubscriber:
    """The latest costmap of a topic, as a numpy grid with its origin and resolution."""

    def __init__(self, node: Node, topic: str) -> None:
        self.node = node
        self._lock = threading.Lock()
        self.costs: np.ndarray | None = None
        self.origin: Point = (0.0, 0.0)
        self.resolution = 0.05
        self.frame_id = ''
        self.handles = [
            node.create_subscription(Costmap, topic, self._on_costmap, COSTMAP_QOS),
            node.create_subscription(CostmapUpdate, topic + '_updates', self._on_update,
                                     UPDATES_QOS)]

    def _on_costmap(self, msg: Costmap) -> None:
        meta = msg.metadata
        grid = np.frombuffer(bytes(msg.data), dtype=np.uint8)
        if grid.size != meta.size_x * meta.size_y:
            self.node.get_logger().warning(
                f'Costmap of {grid.size} cells for {meta.size_x} X {meta.size_y}: ignored')
            return
        with self._lock:
            self.costs = grid.reshape(meta.size_y, meta.size_x).copy()
            self.origin = (meta.origin.position.x, meta.origin.position.y)
            self.resolution = meta.resolution
            self.frame_id = msg.header.frame_id

    def _on_update(self, msg: CostmapUpdate) -> None:
        with self._lock:
            if self.costs is None:
                self.node.get_logger().warning('No costmap received.')
                return
            size_y, size_x = self.costs.shape
            if size_x < msg.x + msg.size_x or size_y < msg.y + msg.size_y:
                self.node.get_logger().warning(
                    f'Update area outside of original map area. Costmap bounds: {size_x} X '
                    f'{size_y}, Update origin: {msg.x}, {msg.y}  bounds: {msg.size_x} X '
                    f'{msg.size_y}')
                return
            patch = np.frombuffer(bytes(msg.data), dtype=np.uint8)
            self.costs[msg.y:msg.y + msg.size_y, msg.x:msg.x + msg.size_x] = \
                patch.reshape(msg.size_y, msg.size_x)

    def get_costmap(self) -> tuple[np.ndarray, Point, float]:
        with self._lock:
            if self.costs is None:
                raise CollisionCheckerException('Costmap is not available')
            return self.costs, self.origin, self.resolution


class FootprintSubscriber:
    """The latest published footprint, in the robot's frame."""

    def __init__(self, node: Node, topic: str, tf: Buffer, robot_base_frame: str,
                 transform_tolerance: float) -> None:
        self.tf = tf
        self.robot_base_frame = robot_base_frame
        self.transform_tolerance = transform_tolerance
        self._msg: PolygonStamped | None = None
        self.handles = [node.create_subscription(PolygonStamped, topic, self._on_footprint,
                                                 qos_profile_system_default)]

    def _on_footprint(self, msg: PolygonStamped) -> None:
        self._msg = msg

    def footprint_in_robot_frame(self) -> list[Point] | None:
        msg = self._msg
        if msg is None or not msg.polygon.points:
            return None
        try:
            t = self.tf.lookup_transform(msg.header.frame_id, self.robot_base_frame,
                                         Time.from_msg(msg.header.stamp),
                                         Duration(seconds=self.transform_tolerance))
        except (TransformException, TypeError):
            try:  # upstream's getCurrentPose falls back on nothing; the latest is close
                t = self.tf.lookup_transform(msg.header.frame_id, self.robot_base_frame,
                                             Time(), Duration(seconds=self.transform_tolerance))
            except (TransformException, TypeError):
                return None
        tr = t.transform
        robot = (tr.translation.x, tr.translation.y,
                 yaw_of(tr.rotation.x, tr.rotation.y, tr.rotation.z, tr.rotation.w))
        return footprint_to_robot_frame([(p.x, p.y) for p in msg.polygon.points], robot)


class CostmapTopicCollisionChecker:
    """isCollisionFree(pose, fetch): `fetch` takes the latest costmap and footprint first."""

    def __init__(self, costmap: CostmapSubscriber, footprint: FootprintSubscriber,
                 name: str) -> None:
        self.costmap_sub = costmap
        self.footprint_sub = footprint
        self.name = name
        self._grid: tuple[np.ndarray, Point, float] | None = None
        self._footprint: list[Point] = []

    def is_collision_free(self, pose: Pose2D, fetch: bool = True) -> bool:
        try:
            return self.score_pose(pose, fetch) < LETHAL_OBSTACLE
        except CollisionCheckerException as error:
            self.costmap_sub.node.get_logger().error(str(error))
            return False

    def score_pose(self, pose: Pose2D, fetch: bool = True) -> float:
        if fetch or self._grid is None:
            self._grid = self.costmap_sub.get_costmap()
        costs, origin, resolution = self._grid
        size = (costs.shape[1], costs.shape[0])
        if world_to_map(pose[0], pose[1], origin, resolution, size) is None:
            raise CollisionCheckerException('Pose Goes Off Grid.')
        if fetch or not self._footprint:
            footprint = self.footprint_sub.footprint_in_robot_frame()
            if footprint is None:
                raise CollisionCheckerException('Current footprint not available.')
            self._footprint = footprint
        return footprint_cost(costs, origin, resolution,
                              transform_footprint(pose, self._footprint))

    def handles(self) -> list[Any]:
        return self.costmap_sub.handles + self.footprint_sub.handles
