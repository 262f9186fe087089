"""The SLAM core, ROS-free: Karto's Mapper as slam_toolbox drives it.

Each scan the robot took after moving minimum_travel_distance or turning
minimum_travel_heading becomes a node: its pose predicted from the last node and the
odometry since, then corrected by matching it against the running buffer (the last
scan_buffer_size nodes within scan_buffer_maximum_scan_distance), linked to the last node by
the match. With do_loop_closing, the nodes near the new one (within
loop_search_maximum_distance) that the graph does not already tie to it, in chains of at
least loop_match_minimum_chain_size consecutive nodes, are tried: a coarse match over the
loop search space, then a fine one; a match that passes the response and variance thresholds
becomes a loop edge and the graph is optimised (pose_graph.optimize).

In localization mode scans are matched against the loaded graph's nodes near the estimate
and kept in a short rolling buffer, the graph itself unchanged.
"""

from __future__ import annotations

import math
from collections import deque
from dataclasses import dataclass, field

import numpy as np

from slam_toolbox_py.pose_graph import (
    Edge,
    compose,
    information_from_covariance,
    optimize,
    relative,
)
from slam_toolbox_py.scan_matcher import (
    LikelihoodField,
    Match,
    Penalties,
    SearchWindow,
    decimate,
    match,
    transform,
)

LOOP_POINTS = 120  # points of the new scan in the coarse loop search (its cost is per point)
FIELD_RESOLUTION_FLOOR = 0.02  # m: finer fields cost more than they give (the fine search
# reads them bilinearly and the field's distances are to exact points)


@dataclass
class MapperParams:
    """Karto's parameters under slam_toolbox's names, with upstream's defaults."""

    use_scan_matching: bool = True
    minimum_travel_distance: float = 0.5
    minimum_travel_heading: float = 0.5
    scan_buffer_size: int = 10
    scan_buffer_maximum_scan_distance: float = 10.0
    link_match_minimum_response_fine: float = 0.1
    link_scan_maximum_distance: float = 1.5
    loop_search_maximum_distance: float = 3.0
    do_loop_closing: bool = True
    loop_match_minimum_chain_size: int = 10
    loop_match_maximum_variance_coarse: float = 3.0
    loop_match_minimum_response_coarse: float = 0.35
    loop_match_minimum_response_fine: float = 0.45
    correlation_search_space_dimension: float = 0.5
    correlation_search_space_resolution: float = 0.01
    correlation_search_space_smear_deviation: float = 0.1
    loop_search_space_dimension: float = 8.0
    loop_search_space_resolution: float = 0.05
    loop_search_space_smear_deviation: float = 0.03
    distance_variance_penalty: float = 0.5
    angle_variance_penalty: float = 1.0
    fine_search_angle_offset: float = 0.00349
    coarse_search_angle_offset: float = 0.349
    coarse_angle_resolution: float = 0.0349
    minimum_angle_penalty: float = 0.9
    minimum_distance_penalty: float = 0.05

    def local_window(self) -> SearchWindow:
        return SearchWindow(
            0.5 * self.correlation_search_space_dimension,
            max(self.correlation_search_space_resolution, FIELD_RESOLUTION_FLOOR),
            self.correlation_search_space_smear_deviation, self.coarse_search_angle_offset,
            self.coarse_angle_resolution, self.fine_search_angle_offset)

    def loop_window(self) -> SearchWindow:
        return SearchWindow(
            0.5 * self.loop_search_space_dimension,
            max(self.loop_search_space_resolution, FIELD_RESOLUTION_FLOOR),
            max(self.loop_search_space_smear_deviation, 0.5 * self.loop_search_space_resolution),
            self.coarse_search_angle_offset, self.coarse_angle_resolution,
            self.fine_search_angle_offset)

    def penalties(self) -> Penalties:
        return Penalties(self.distance_variance_penalty, self.angle_variance_penalty,
                         self.minimum_distance_penalty, self.minimum_angle_penalty)


@dataclass
class ScanNode:
    id: int
    odom: np.ndarray  # the odometry pose the scan was taken at
    pose: np.ndarray  # corrected, in the map frame
    hits: np.ndarray  # (N, 2) robot frame
    misses: np.ndarray  # (M, 2) robot frame: ends of beams that saw nothing
    origin: np.ndarray  # the laser in the robot frame
    stamp: float
    covariance: np.ndarray = field(default_factory=lambda: np.eye(3) * 1e-4)


class Mapper:
    def __init__(self, params: MapperParams) -> None:
        self.params = params
        self.nodes: list[ScanNode] = []
        self.edges: list[Edge] = []
        self.loop_closures = 0
        self._last: tuple[np.ndarray, ScanNode] | None = None  # odom pose, node: this session
        self._start_pose: np.ndarray | None = None  # where the session's first scan goes
        self._localized: tuple[np.ndarray, np.ndarray] | None = None  # odom, map pose
        self._rolling: deque[tuple[np.ndarray, np.ndarray]] = deque(
            maxlen=max(1, params.scan_buffer_size))

    # -- sessions -------------------------------------------------------------------------
    def start_at(self, pose: np.ndarray | None) -> None:
        """The next scan starts a session at `pose` (map frame; None: the first node's),
        matched against the nodes there, e.g. after deserializing a graph."""
        if pose is None and self.nodes:
            pose = self.nodes[0].pose.copy()
        self._start_pose = None if pose is None else np.asarray(pose, float)
        self._last = None
        self._localized = None
        self._rolling.clear()

    def reset(self) -> None:
        self.nodes.clear()
        self.edges.clear()
        self.loop_closures = 0
        self.start_at(None)

    def poses(self) -> dict[int, np.ndarray]:
        return {node.id: node.pose for node in self.nodes}

    def moved_enough(self, odom: np.ndarray) -> bool:
        if self._last is None:
            return True
        last = self._last[0]
        return (math.hypot(*(odom[:2] - last[:2])) >= self.params.minimum_travel_distance
                or abs(relative(last, odom)[2]) >= self.params.minimum_travel_heading)

    # -- mapping --------------------------------------------------------------------------
    def process(self, odom: np.ndarray, hits: np.ndarray, misses: np.ndarray,
                origin: np.ndarray, stamp: float) -> ScanNode | None:
        """Add the scan as a node if the robot moved enough; None if it did not (or the
        scan has too few points to match)."""
        if not self.moved_enough(odom) or len(hits) < 3:
            return None
        p = self.params
        if self._last is not None:
            prior = compose(self._last[1].pose, relative(self._last[0], odom))
            reference = self._running_buffer(prior)
        elif self._start_pose is not None:
            prior = self._start_pose
            reference = self._near(prior, p.scan_buffer_maximum_scan_distance)
        else:
            prior, reference = odom.copy(), []
        pose, cov = prior, np.diag([0.05, 0.05, 0.02]) ** 2
        if p.use_scan_matching and reference:
            result = self._match(reference, hits, prior, p.local_window())
            if result.response >= p.link_match_minimum_response_fine:
                pose, cov = result.pose, result.covariance
        node = ScanNode(len(self.nodes), odom.copy(), pose.copy(), hits, misses, origin,
                        stamp, cov)
        self.nodes.append(node)
        if self._last is not None:
            anchor = self._last[1]
        elif reference:  # a new session: tie it to the nearest node it was matched against
            anchor = min(reference, key=lambda n: math.hypot(*(n.pose[:2] - pose[:2])))
        else:
            anchor = None
        if anchor is not None:
            self.edges.append(Edge(anchor.id, node.id, relative(anchor.pose, node.pose),
                                   information_from_covariance(cov)))
        self._last = (odom.copy(), node)
        self._start_pose = None
        if p.do_loop_closing and self._try_loop_closure(node):
            self.optimize()
        return node

    def optimize(self) -> None:
        poses = optimize(np.array([n.pose for n in self.nodes]), self.edges)
        for node, pose in zip(self.nodes, poses, strict=True):
            node.pose = pose

    def map_to_odom(self) -> np.ndarray | None:
        """The map -> odom transform (x, y, yaw) of the latest corrected pose."""
        if self._localized is not None:
            odom, pose = self._localized
        elif self._last is not None:
            odom, pose = self._last[0], self._last[1].pose
        else:
            return None
        return compose(pose, _inverse(odom))

    def latest_pose(self) -> np.ndarray | None:
        if self._localized is not None:
            return self._localized[1]
        return None if self._last is None else self._last[1].pose

    def _running_buffer(self, prior: np.ndarray) -> list[ScanNode]:
        p = self.params
        recent = self.nodes[-p.scan_buffer_size:] if p.scan_buffer_size > 0 else []
        return [n for n in recent if math.hypot(*(n.pose[:2] - prior[:2]))
                <= p.scan_buffer_maximum_scan_distance]

    def _near(self, pose: np.ndarray, distance: float) -> list[ScanNode]:
        return [n for n in self.nodes if math.hypot(*(n.pose[:2] - pose[:2])) <= distance]

    def _field(self, reference: list[ScanNode], window: SearchWindow) -> LikelihoodField:
        points = np.concatenate([transform(n.hits, n.pose) for n in reference])
        return LikelihoodField.from_points(points, window.resolution, window.smear,
                                           margin=window.linear + 3 * window.smear)

    def _match(self, reference: list[ScanNode], hits: np.ndarray, prior: np.ndarray,
               window: SearchWindow, points: int | None = None) -> Match:
        field = self._field(reference, window)
        scan = hits if points is None else decimate(hits, points)
        return match(field, scan, prior, window, self.params.penalties())

    # -- loop closure ---------------------------------------------------------------------
    def _linked_near(self, node: ScanNode) -> set[int]:
        """Nodes the graph ties to `node` through nodes all within loop_search_maximum_
        distance of it (Karto's FindNearLinkedScans): no loop to close with those."""
        limit = self.params.loop_search_maximum_distance
        neighbours: dict[int, list[int]] = {}
        for e in self.edges:
            neighbours.setdefault(e.i, []).append(e.j)
            neighbours.setdefault(e.j, []).append(e.i)
        seen, todo = {node.id}, [node.id]
        while todo:
            for other in neighbours.get(todo.pop(), []):
                if other not in seen and math.hypot(
                        *(self.nodes[other].pose[:2] - node.pose[:2])) <= limit:
                    seen.add(other)
                    todo.append(other)
        return seen

    def _chains(self, node: ScanNode) -> list[list[ScanNode]]:
        p = self.params
        linked = self._linked_near(node)
        candidates = [n for n in self.nodes[:node.id]
                      if n.id not in linked and math.hypot(*(n.pose[:2] - node.pose[:2]))
                      <= p.loop_search_maximum_distance]
        chains: list[list[ScanNode]] = []
        for n in candidates:
            if chains and chains[-1][-1].id == n.id - 1:
                chains[-1].append(n)
            else:
                chains.append([n])
        return [c for c in chains if len(c) >= p.loop_match_minimum_chain_size]

    def _try_loop_closure(self, node: ScanNode) -> bool:
        p = self.params
        closed = False
        for chain in self._chains(node):
            coarse = self._match(chain, node.hits, node.pose, p.loop_window(), LOOP_POINTS)
            if (coarse.response < p.loop_match_minimum_response_coarse
                    or coarse.covariance[0, 0] > p.loop_match_maximum_variance_coarse
                    or coarse.covariance[1, 1] > p.loop_match_maximum_variance_coarse):
                continue
            fine = self._match(chain, node.hits, coarse.pose, p.local_window())
            if fine.response < p.loop_match_minimum_response_fine:
                continue
            anchor = min(chain, key=lambda n: math.hypot(*(n.pose[:2] - fine.pose[:2])))
            self.edges.append(Edge(anchor.id, node.id, relative(anchor.pose, fine.pose),
                                   information_from_covariance(fine.covariance), loop=True))
            self.loop_closures += 1
            closed = True
        return closed

    # -- localization ---------------------------------------------------------------------
    def localize(self, odom: np.ndarray, hits: np.ndarray, stamp: float
                 ) -> np.ndarray | None:
        """Match the scan against the graph near the estimate; the corrected pose, or None
        (not moved enough, nothing to match against, or no start pose)."""
        p = self.params
        if self._localized is not None:
            last_odom, last_pose = self._localized
            if (math.hypot(*(odom[:2] - last_odom[:2])) < p.minimum_travel_distance
                    and abs(relative(last_odom, odom)[2]) < p.minimum_travel_heading):
                return None
            prior = compose(last_pose, relative(last_odom, odom))
        elif self._start_pose is not None:
            prior = self._start_pose
        else:
            return None
        reference = self._near(prior, p.scan_buffer_maximum_scan_distance)
        if len(hits) < 3 or not reference:
            return None
        # the graph's nodes there and the last localized scans (upstream's rolling buffer)
        recent = [ScanNode(-1, pose, pose, scan, np.zeros((0, 2)), np.zeros(2), 0.0)
                  for pose, scan in self._rolling]
        result = self._match(reference + recent, hits, prior, p.local_window())
        pose = result.pose if result.response >= p.link_match_minimum_response_fine else prior
        self._localized = (odom.copy(), pose.copy())
        self._start_pose = None
        self._rolling.append((pose.copy(), hits))
        return pose


def _inverse(pose: np.ndarray) -> np.ndarray:
    c, s = math.cos(pose[2]), math.sin(pose[2])
    return np.array([-c * pose[0] - s * pose[1], s * pose[0] - c * pose[1], -pose[2]])
