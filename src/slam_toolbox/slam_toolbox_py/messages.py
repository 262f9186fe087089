"""Between ROS messages and the mapper's arrays: scans to points, the grid to an
OccupancyGrid, the graph to markers, poses to transforms."""

from __future__ import annotations

import math
from array import array

import numpy as np
from geometry_msgs.msg import Point, Pose, TransformStamped
from nav_msgs.msg import OccupancyGrid
from sensor_msgs.msg import LaserScan
from std_msgs.msg import ColorRGBA
from visualization_msgs.msg import Marker, MarkerArray

from slam_toolbox_py.mapper import ScanNode
from slam_toolbox_py.pose_graph import Edge


def yaw_of(q) -> float:
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def pose2d(transform) -> np.ndarray:
    """x, y, yaw of a geometry_msgs Transform."""
    return np.array([transform.translation.x, transform.translation.y,
                     yaw_of(transform.rotation)])


def pose_msg(pose: np.ndarray) -> Pose:
    msg = Pose()
    msg.position.x, msg.position.y = float(pose[0]), float(pose[1])
    msg.orientation.z, msg.orientation.w = math.sin(pose[2] / 2), math.cos(pose[2] / 2)
    return msg


def transform_msg(pose: np.ndarray, parent: str, child: str, stamp) -> TransformStamped:
    msg = TransformStamped()
    msg.header.frame_id, msg.child_frame_id = parent, child
    msg.header.stamp = stamp
    msg.transform.translation.x, msg.transform.translation.y = float(pose[0]), float(pose[1])
    msg.transform.rotation.z = math.sin(pose[2] / 2)
    msg.transform.rotation.w = math.cos(pose[2] / 2)
    return msg


def scan_points(scan: LaserScan, laser: np.ndarray, max_laser_range: float
                ) -> tuple[np.ndarray, np.ndarray, int]:
    """(hits, misses, bad): hit points and the ends of beams that saw nothing within range,
    in the robot frame of the laser pose `laser` (x, y, yaw); `bad` counts NaN readings,
    which are neither (nor are -inf, "too close", and readings below range_min)."""
    ranges = np.asarray(scan.ranges, dtype=np.float64)
    angles = scan.angle_min + np.arange(ranges.size) * scan.angle_increment + laser[2]
    limit = min(scan.range_max, max_laser_range) if max_laser_range > 0 else scan.range_max
    with np.errstate(invalid='ignore'):
        hit = np.isfinite(ranges) & (ranges >= scan.range_min) & (ranges <= limit)
        miss = (ranges == np.inf) | (np.isfinite(ranges) & (ranges > limit))
    bad = int(np.isnan(ranges).sum())

    def points(mask: np.ndarray, distance: np.ndarray) -> np.ndarray:
        a = angles[mask]
        return np.stack([laser[0] + distance * np.cos(a), laser[1] + distance * np.sin(a)],
                        axis=1)

    return points(hit, ranges[hit]), points(miss, np.full(int(miss.sum()), limit)), bad


def grid_msg(data: np.ndarray, width: int, height: int, origin: tuple[float, float],
             resolution: float, frame: str, stamp) -> OccupancyGrid:
    msg = OccupancyGrid()
    msg.header.frame_id, msg.header.stamp = frame, stamp
    msg.info.map_load_time = stamp
    msg.info.resolution = float(resolution)
    msg.info.width, msg.info.height = width, height
    msg.info.origin.position.x, msg.info.origin.position.y = float(origin[0]), float(origin[1])
    msg.info.origin.orientation.w = 1.0
    msg.data = array('b', data.tobytes())
    return msg


def graph_markers(nodes: list[ScanNode], edges: list[Edge], frame: str, stamp
                  ) -> MarkerArray:
    """The nodes as spheres, odometry/scan-match links blue, loop closures red."""
    array = MarkerArray()
    spheres = Marker(ns='slam_toolbox', id=0, type=Marker.SPHERE_LIST, action=Marker.ADD)
    spheres.scale.x = spheres.scale.y = spheres.scale.z = 0.1
    spheres.color = ColorRGBA(r=1.0, g=0.0, b=0.0, a=1.0)
    spheres.points = [Point(x=float(n.pose[0]), y=float(n.pose[1])) for n in nodes]
    array.markers.append(spheres)
    for marker_id, loop, color in ((1, False, (0.0, 0.0, 1.0)), (2, True, (1.0, 0.0, 0.0))):
        lines = Marker(ns='slam_toolbox_edges', id=marker_id, type=Marker.LINE_LIST,
                       action=Marker.ADD)
        lines.scale.x = 0.03
        lines.color = ColorRGBA(r=color[0], g=color[1], b=color[2], a=1.0)
        for e in edges:
            if e.loop == loop and e.i < len(nodes) and e.j < len(nodes):
                a, b = nodes[e.i].pose, nodes[e.j].pose
                lines.points += [Point(x=float(a[0]), y=float(a[1])),
                                 Point(x=float(b[0]), y=float(b[1]))]
        array.markers.append(lines)
    for marker in array.markers:
        marker.header.frame_id, marker.header.stamp = frame, stamp
        marker.pose.orientation.w = 1.0
    return array
