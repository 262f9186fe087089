"""`ros2 run nav2_smoother smoother_server`: Nav2's path smoother server, a lifecycle node.

The action `smooth_path` (nav2_msgs/action/SmoothPath) smooths a path with the plugin named by
`smoother_id` (the `smoother_plugins`; only nav2_smoother::SimpleSmoother exists here), within
`max_smoothing_duration`, publishes it on `plan_smoothed` and, with `check_for_collisions`,
checks the robot's footprint at every pose against the costmap it receives on
`costmap_topic` (global_costmap/costmap_raw) with the footprint of `footprint_topic`, as
upstream's CostmapTopicCollisionChecker. Failures end ABORTED with SmoothPath's error codes.
"""

from __future__ import annotations

import math
import sys
import threading
import time
from typing import Any

import numpy as np
from geometry_msgs.msg import PolygonStamped
from nav2_msgs.action import SmoothPath
from nav2_msgs.msg import Costmap
from nav2_util.lifecycle_node import LifecycleNode, run_server
from nav2_util.parameters import declare_checked, warn_unknown_parameters
from nav_msgs.msg import Path
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.callback_groups import ReentrantCallbackGroup
from rclpy.duration import Duration
from rclpy.lifecycle import State, TransitionCallbackReturn
from rclpy.qos import DurabilityPolicy, QoSProfile
from rclpy.time import Time
from tf2_ros import Buffer, TransformListener

from nav2_smoother.simple_smoother import GridView, SmootherParams, SmootherTimedOut, smooth

SMOOTHER_TYPES = {'nav2_smoother::SimpleSmoother'}
LETHAL_OBSTACLE = 254
Result = SmoothPath.Result


class SmootherError(Exception):
    def __init__(self, code: int, text: str) -> None:
        super().__init__(text)
        self.code = code


def _yaw(q: Any) -> float:
    return math.atan2(2.0 * (q.w * q.z + q.x * q.y), 1.0 - 2.0 * (q.y * q.y + q.z * q.z))


def _quaternion(yaw: float) -> tuple[float, float]:
    return math.sin(yaw / 2.0), math.cos(yaw / 2.0)


class SmootherServer(LifecycleNode):
    def __init__(self) -> None:
        super().__init__('smoother_server')
        self.get_logger().info('Creating smoother server')
        self.costmap_topic = declare_checked(self, 'costmap_topic',
                                             'global_costmap/costmap_raw')
        self.footprint_topic = declare_checked(self, 'footprint_topic',
                                               'global_costmap/published_footprint')
        self.robot_base_frame = declare_checked(self, 'robot_base_frame', 'base_link')
        self.transform_tolerance = declare_checked(self, 'transform_tolerance', 0.1)
        self.smoother_ids: list[str] = declare_checked(self, 'smoother_plugins',
                                                       ['simple_smoother'])
        declare_checked(self, 'action_server_result_timeout', 10.0)
        self.types: dict[str, str] = {}
        self.params: dict[str, SmootherParams] = {}
        defaults = SmootherParams()
        for sid in self.smoother_ids:
            default = 'nav2_smoother::SimpleSmoother' if sid == 'simple_smoother' else ''
            self.types[sid] = declare_checked(self, f'{sid}.plugin', default)
            self.params[sid] = SmootherParams(**{
                key: declare_checked(self, f'{sid}.{key}', getattr(defaults, key))
                for key in defaults.__dataclass_fields__})
        warn_unknown_parameters(self)
        self._handles: list[Any] = []
        self._action: ActionServer | None = None
        self._plan_pub = None
        self.tf_buffer: Buffer | None = None
        self._tf_listener: TransformListener | None = None
        self.costmap: Costmap | None = None
        self.footprint: PolygonStamped | None = None
        self._lock = threading.Lock()  # one path smoothed at a time
        self._warned_no_id = False

    # --- lifecycle -----------------------------------------------------------------------
    def on_configure(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Configuring smoother server')
        for sid in self.smoother_ids:
            kind = self.types[sid].replace('/', '::')
            if kind not in SMOOTHER_TYPES:
                self.get_logger().fatal(
                    f"Failed to create smoother. Exception: Failed to load plugin '{kind}' "
                    f"for {sid}.plugin: the smoothers available are "
                    f"{', '.join(sorted(SMOOTHER_TYPES))}")
                return TransitionCallbackReturn.FAILURE
            self.get_logger().info(f'Created smoother : {sid} of type {kind}')
        self.get_logger().info(
            f"Smoother Server has {' '.join(self.smoother_ids)}  smoothers available.")
        self.tf_buffer = Buffer(node=self)
        self._tf_listener = TransformListener(self.tf_buffer, self, spin_thread=True)
        latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        self._handles = [
            self.create_subscription(Costmap, self.costmap_topic, self.on_costmap, latched),
            self.create_subscription(PolygonStamped, self.footprint_topic, self.on_footprint,
                                     10)]
        self._plan_pub = self.create_lifecycle_publisher(Path, 'plan_smoothed', 1)
        self._action = ActionServer(
            self, SmoothPath, 'smooth_path', self.on_goal,
            goal_callback=self.on_goal_request,
            cancel_callback=lambda _request: CancelResponse.ACCEPT,
            callback_group=ReentrantCallbackGroup())
        return TransitionCallbackReturn.SUCCESS

    def on_activate(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Activating')
        return super().on_activate(state)

    def release(self) -> None:
        if self._action is not None:
            self._action.destroy()
        for handle in self._handles:
            self.destroy_subscription(handle)
        if self._plan_pub is not None:
            self.destroy_lifecycle_publisher(self._plan_pub)
        if self._tf_listener is not None:
            self._tf_listener.unregister()
        self._action = self._plan_pub = self._tf_listener = self.tf_buffer = None
        self._handles = []

    # --- inputs --------------------------------------------------------------------------
    def on_costmap(self, msg: Costmap) -> None:
        self.costmap = msg

    def on_footprint(self, msg: PolygonStamped) -> None:
        self.footprint = msg

    # --- goals ---------------------------------------------------------------------------
    def on_goal_request(self, _goal: Any) -> GoalResponse:
        if not self.is_active():
            self.get_logger().warning('Action server is inactive. Rejecting the goal.')
            return GoalResponse.REJECT
        return GoalResponse.ACCEPT

    def on_goal(self, handle: Any) -> Result:
        with self._lock:
            started = time.monotonic()
            self.get_logger().info('Received a path to smooth.')
            result = Result()
            goal = handle.request
            try:
                sid = self._smoother_id(goal.smoother_id)
                result.path = goal.path
                if not goal.path.poses:
                    self.get_logger().warning('Requested path to smooth is empty')
                    raise SmootherError(Result.INVALID_PATH,
                                        'Requested path to smooth is invalid')
                max_time = Duration.from_msg(goal.max_smoothing_duration).nanoseconds * 1e-9
                result.was_completed = self._smooth(result.path, self.params[sid], max_time)
                elapsed = time.monotonic() - started
                result.smoothing_duration = Duration(seconds=elapsed).to_msg()
                if not result.was_completed:
                    self.get_logger().info(
                        f'Smoother {sid} did not complete smoothing in specified time limit'
                        f'({max_time:f} seconds) and was interrupted after {elapsed:f} seconds')
                self._plan_pub.publish(result.path)
                if goal.check_for_collisions:
                    self._check_collisions(result.path)
            except SmootherError as error:
                self.get_logger().error(str(error))
                result.error_code, result.error_msg = error.code, str(error)
                handle.abort()
                return result
            handle.succeed()
            return result

    def _smoother_id(self, name: str) -> str:
        if name in self.params:
            return name
        if not name and len(self.params) == 1:
            if not self._warned_no_id:
                self.get_logger().warning(
                    'No smoother was specified in action call. Server will use only plugin '
                    f"loaded {' '.join(self.smoother_ids)} . This warning will appear once.")
                self._warned_no_id = True
            return self.smoother_ids[0]
        self.get_logger().error(
            f'SmoothPath called with smoother name {name}, which does not exist. Available '
            f"smoothers are: {' '.join(self.smoother_ids)} .")
        raise SmootherError(Result.INVALID_SMOOTHER, f'Invalid Smoother: {name}')

    def _grid(self) -> GridView | None:
        msg = self.costmap
        if msg is None:
            return None
        meta = msg.metadata
        data = np.frombuffer(bytes(msg.data), dtype=np.uint8).reshape(
            meta.size_y, meta.size_x)
        return GridView(data, meta.resolution, meta.origin.position.x, meta.origin.position.y)

    def _smooth(self, path: Path, params: SmootherParams, max_time: float) -> bool:
        xy = np.array([[p.pose.position.x, p.pose.position.y] for p in path.poses])
        yaw = np.array([_yaw(p.pose.orientation) for p in path.poses])
        if not np.isfinite(xy).all() or not np.isfinite(yaw).all():
            raise SmootherError(Result.INVALID_PATH, 'Requested path to smooth is invalid')
        try:
            xy, yaw, done = smooth(xy, yaw, params, self._grid(), max_time)
        except SmootherTimedOut as error:
            self.get_logger().warning(
                f'Smoothing time exceeded allowed duration of {max_time:0.2f}.')
            raise SmootherError(Result.TIMEOUT, str(error)) from None
        for pose, (x, y), theta in zip(path.poses, xy, yaw, strict=True):
            pose.pose.position.x, pose.pose.position.y = float(x), float(y)
            pose.pose.orientation.z, pose.pose.orientation.w = _quaternion(float(theta))
            pose.pose.orientation.x = pose.pose.orientation.y = 0.0
        return done

    def _footprint_in_robot_frame(self) -> np.ndarray | None:
        msg = self.footprint
        if msg is None or self.tf_buffer is None:
            return None
        points = np.array([[p.x, p.y] for p in msg.polygon.points])
        try:
            t = self.tf_buffer.lookup_transform(self.robot_base_frame, msg.header.frame_id,
                                                Time(), Duration(
                                                    seconds=self.transform_tolerance))
        except Exception:  # no transform: no footprint, as upstream's subscriber
            return None
        tr = t.transform
        theta = _yaw(tr.rotation)
        c, s = math.cos(theta), math.sin(theta)
        return np.stack([tr.translation.x + c * points[:, 0] - s * points[:, 1],
                         tr.translation.y + s * points[:, 0] + c * points[:, 1]], axis=1)

    def _check_collisions(self, path: Path) -> None:
        grid = self._grid()
        footprint = self._footprint_in_robot_frame()
        for pose in path.poses:
            x, y = pose.pose.position.x, pose.pose.position.y
            theta = _yaw(pose.pose.orientation)
            if grid is None or footprint is None or \
                    self._footprint_cost(grid, footprint, x, y, theta) >= LETHAL_OBSTACLE:
                self.get_logger().error(
                    f'Smoothed path leads to a collision at x: {x:f}, y: {y:f}, '
                    f'theta: {theta:f}')
                raise SmootherError(
                    Result.SMOOTHED_PATH_IN_COLLISION,
                    f'Smoothed Path collided atX: {x:f}Y: {y:f}Theta: {theta:f}')

    @staticmethod
    def _footprint_cost(grid: GridView, footprint: np.ndarray, x: float, y: float,
                        theta: float) -> int:
        """The highest cost on the footprint's outline at (x, y, theta)."""
        c, s = math.cos(theta), math.sin(theta)
        corners = np.stack([x + c * footprint[:, 0] - s * footprint[:, 1],
                            y + s * footprint[:, 0] + c * footprint[:, 1]], axis=1)
        samples = [corners]
        for a, b in zip(corners, np.roll(corners, -1, axis=0), strict=True):
            steps = max(2, int(np.hypot(*(b - a)) / grid.resolution) + 1)
            samples.append(a + np.linspace(0.0, 1.0, steps)[:, None] * (b - a))
        # off the grid reads as unknown (255): above lethal, as upstream's checker scores it
        return int(grid.costs(np.concatenate(samples)).max())

def main(args: list[str] | None = None) -> int:
    return run_server(SmootherServer, args)


if __name__ == '__main__':
    sys.exit(main())
