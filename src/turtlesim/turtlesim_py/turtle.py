"""One turtle: pose, pen, its topics, services and the rotate_absolute action."""

from __future__ import annotations

import math
import random
from collections.abc import Callable
from typing import TYPE_CHECKING

from geometry_msgs.msg import Twist
from node_runtime.repeat_log import RepeatedLog
from rclpy.action import ActionServer, CancelResponse, GoalResponse
from rclpy.action.server import ServerGoalHandle
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from rclpy.task import Future
from turtlesim.action import RotateAbsolute
from turtlesim.msg import Color, Pose
from turtlesim.srv import SetPen, TeleportAbsolute, TeleportRelative

from turtlesim_py import sim
from turtlesim_py.canvas import SHELL_COLOURS
from turtlesim_py.sim import CANVAS_HEIGHT, CMD_VEL_TIMEOUT, FLOAT32_MAX, integrate

if TYPE_CHECKING:
    from turtlesim_py.canvas import Canvas
    from turtlesim_py.frame import TurtleFrame

TOPIC_QOS = QoSProfile(depth=7, history=HistoryPolicy.KEEP_LAST,
                       reliability=ReliabilityPolicy.RELIABLE,
                       durability=DurabilityPolicy.VOLATILE)
DEFAULT_PEN = (179, 184, 255)
DEFAULT_PEN_WIDTH = 3


class _Goal:
    """The active rotate_absolute goal and the future its execute coroutine awaits."""

    def __init__(self, handle: ServerGoalHandle, start_theta: float) -> None:
        self.handle = handle
        self.start_theta = start_theta
        self.result = RotateAbsolute.Result()
        self.feedback = RotateAbsolute.Feedback()
        self.done = Future()

    def finish(self, terminal: Callable[[], None]) -> None:
        if self.handle.is_active:
            terminal()
        if not self.done.done():
            self.done.set_result(self.result)


class Turtle:
    def __init__(self, frame: TurtleFrame, name: str, x: float, y: float, theta: float,
                 action_server: ActionServer | None = None) -> None:
        self.frame = frame
        self.name = name
        self.log = frame.get_logger()
        # Per turtle: a respawned turtle1 is a new source, its first bad command is logged.
        self.repeated = RepeatedLog(self.log)
        self.x = x
        self.y_int = sim.CANVAS_HEIGHT - y
        self.theta = theta
        self.vx = self.vy = self.w = 0.0
        self.last_command = frame.now_seconds()
        self.pen_on = True
        self.pen_rgb = DEFAULT_PEN
        self.pen_width = DEFAULT_PEN_WIDTH
        self.shell = random.choice(SHELL_COLOURS)
        self.teleports: list[tuple[str, float, float, float]] = []
        self.goal: _Goal | None = None
        self._pending: dict[int, _Goal] = {}
        self._pose = Pose()
        self._color = Color()

        node = frame
        locked = frame.locked
        # Taken by the tick itself (update), never by the executor: see PolledByTick.
        self.cmd_vel_sub = node.create_subscription(
            Twist, f'{name}/cmd_vel', self._on_cmd_vel, TOPIC_QOS,
            callback_group=frame.polled_by_tick)
        self.pose_pub = node.create_publisher(Pose, f'{name}/pose', TOPIC_QOS)
        self.color_pub = node.create_publisher(Color, f'{name}/color_sensor', TOPIC_QOS)
        # The handles' own methods for the per-tick calls: the rclpy wrappers add a type
        # check and a use-count context per call (update() explains why that is safe).
        self._take = self.cmd_vel_sub.handle.take_message
        self._pose_subscribers = self.pose_pub.handle.get_subscription_count
        self._publish_pose = self.pose_pub.handle.publish
        self._color_subscribers = self.color_pub.handle.get_subscription_count
        self._publish_color = self.color_pub.handle.publish
        self.services = [
            node.create_service(SetPen, f'{name}/set_pen', locked(self._on_set_pen)),
            node.create_service(TeleportAbsolute, f'{name}/teleport_absolute',
                                locked(self._on_teleport_absolute)),
            node.create_service(TeleportRelative, f'{name}/teleport_relative',
                                locked(self._on_teleport_relative)),
        ]
        for service in self.services:
            frame.configure_introspection(service)
        if action_server is None:
            action_server = ActionServer(
                node, RotateAbsolute, f'{name}/rotate_absolute',
                execute_callback=self._execute, goal_callback=self._on_goal,
                handle_accepted_callback=locked(self._on_accepted),
                cancel_callback=lambda _handle: CancelResponse.ACCEPT)
        else:  # a retired server of a killed turtle with the same name: adopt it
            action_server.register_execute_callback(self._execute)
            action_server.register_goal_callback(self._on_goal)
            action_server.register_handle_accepted_callback(locked(self._on_accepted))
        self.action_server = action_server

    # ---------------------------------------------------------------- inputs
    def _on_cmd_vel(self, msg: Twist, now: float) -> None:
        linear = msg.linear
        vx, vy, w = linear.x, linear.y, msg.angular.z
        # One chained comparison for the common case (NaN fails it too); the loop names
        # the offending field.
        if not -FLOAT32_MAX <= vx <= FLOAT32_MAX or not -FLOAT32_MAX <= vy <= FLOAT32_MAX \
                or not -FLOAT32_MAX <= w <= FLOAT32_MAX:
            for field, value in (('linear.x', vx), ('linear.y', vy), ('angular.z', w)):
                if not sim.finite_float32(value):
                    self.repeated.error(
                        ('cmd_vel', field),
                        f'Ignoring {self.name}/cmd_vel: {field}={value} is not allowed '
                        f'(allowed: finite values within +-{sim.FLOAT32_MAX:.7g})')
                    return
        self.last_command = now
        self.vx = vx
        if self.frame.holonomic():
            self.vy = vy
        self.w = w
        if self.goal is not None:
            self.log.warning('Velocity command received during rotation goal. Aborting goal')
            goal, self.goal = self.goal, None
            goal.finish(goal.handle.abort)

    def _on_set_pen(self, request: SetPen.Request, response: SetPen.Response) -> SetPen.Response:
        if request.off:
            self.pen_on = False
        else:
            self.pen_on = True
            self.pen_rgb = (request.r, request.g, request.b)
            self.pen_width = request.width or 1
        return response

    def _check_floats(self, service: str, **fields: float) -> bool:
        for field, value in fields.items():
            if not math.isfinite(value):
                self.log.error(
                    f'Refusing {self.name}/{service}: {field}={value} is not allowed '
                    f'(allowed: finite numbers)')
                return False
        return True

    def _on_teleport_absolute(self, request: TeleportAbsolute.Request,
                              response: TeleportAbsolute.Response) -> TeleportAbsolute.Response:
        if self._check_floats('teleport_absolute', x=request.x, y=request.y,
                              theta=request.theta):
            self.teleports.append(('absolute', request.x, request.y, request.theta))
        return response

    def _on_teleport_relative(self, request: TeleportRelative.Request,
                              response: TeleportRelative.Response) -> TeleportRelative.Response:
        if self._check_floats('teleport_relative', linear=request.linear,
                              angular=request.angular):
            self.teleports.append(('relative', request.linear, request.angular, 0.0))
        return response

    # ---------------------------------------------------------------- action
    def _on_goal(self, goal: RotateAbsolute.Goal) -> GoalResponse:
        if not math.isfinite(goal.theta):
            self.log.error(
                f'Rejecting {self.name}/rotate_absolute goal: theta={goal.theta} is not allowed '
                f'(allowed: finite numbers)')
            return GoalResponse.REJECT
        return GoalResponse.ACCEPT

    def _on_accepted(self, handle: ServerGoalHandle) -> None:
        if self.goal is not None:
            self.log.warning(
                'Rotation goal received before a previous goal finished. Aborting previous goal')
            previous, self.goal = self.goal, None
            previous.finish(previous.handle.abort)
        self.goal = _Goal(handle, self.theta)
        self._pending[id(handle)] = self.goal
        handle.execute()

    async def _execute(self, handle: ServerGoalHandle) -> RotateAbsolute.Result:
        goal = self._pending.pop(id(handle))
        return await goal.done

    def _step_goal(self, now: float) -> None:
        goal = self.goal
        if goal is None:
            return
        handle = goal.handle
        if not handle.is_active:
            self.goal = None
            return
        if handle.is_cancel_requested:
            self.log.info('Rotation goal canceled')
            self.goal = None
            self.vx = self.vy = self.w = 0.0
            goal.finish(handle.canceled)
            return
        step = sim.rotate_step(self.theta, handle.request.theta, goal.start_theta)
        goal.result.delta = step.delta
        goal.feedback.remaining = step.remaining
        handle.publish_feedback(goal.feedback)
        if step.done:
            self.log.info('Rotation goal completed successfully')
            self.goal = None
            self.vx = self.vy = self.w = 0.0
            goal.finish(handle.succeed)
        else:
            self.vx = self.vy = 0.0
            self.w = step.angular_velocity
            self.last_command = now

    # ---------------------------------------------------------------- tick
    def update(self, dt: float, now: float, canvas: Canvas) -> bool:
        """One tick of this turtle (upstream's order, see docs/turtlesim.md); True when
        something visible changed.

        Runs for every turtle on every tick, so it calls the rclpy handles directly (taken
        in __init__; the frame's lock keeps them alive: a turtle is destroyed under it) and
        keeps to local variables: with 1000 turtles each microsecond here is a millisecond
        of the 16 ms tick (docs/speed.md).
        """
        take = self._take
        while (taken := take(Twist, False)) is not None:
            self._on_cmd_vel(taken[0], now)
        changed = False
        if self.teleports:
            for kind, a, b, c in self.teleports:
                old_x, old_y = self.x, self.y_int
                if kind == 'relative':
                    self.x, self.y_int, self.theta = sim.teleport_relative(
                        self.x, self.y_int, self.theta, a, b)
                else:
                    self.x, self.y_int, self.theta = sim.teleport_absolute(a, b, c)
                if self.pen_on:
                    canvas.draw_line(self.x, self.y_int, old_x, old_y, self.pen_rgb,
                                     self.pen_width)
            self.teleports.clear()
            changed = True
        if self.goal is not None:
            self._step_goal(now)
        if now - self.last_command > CMD_VEL_TIMEOUT:
            self.vx = self.vy = self.w = 0.0
        vx, vy, w = self.vx, self.vy, self.w
        old_x, old_y, old_theta = self.x, self.y_int, self.theta
        x, y, theta = integrate(old_x, old_y, old_theta, vx, vy, w, dt)
        if sim.hits_wall(x, y):
            self.log.warning(sim.wall_warning(x, y))
            x, y = sim.clamp_to_walls(x, y)
        self.x, self.y_int, self.theta = x, y, theta

        # Nobody listening: skip building and publishing. A subscriber that matches later
        # could not have received this sample anyway (volatile durability).
        if self._pose_subscribers():
            pose = self._pose
            pose.x = x
            pose.y = CANVAS_HEIGHT - y
            pose.theta = theta
            pose.linear_velocity = min(sim.pose_linear_velocity(vx, vy), FLOAT32_MAX)
            pose.angular_velocity = w
            self._publish_pose(pose)
        if self._color_subscribers():
            color = self._color
            # rgb_at draws the segments queued so far (this tick's earlier turtles) first.
            color.r, color.g, color.b = canvas.rgb_at(*sim.to_pixel(x, y))
            self._publish_color(color)

        if x != old_x or y != old_y:
            if self.pen_on:
                canvas.draw_line(old_x, old_y, x, y, self.pen_rgb, self.pen_width)
            return True
        return changed or theta != old_theta

    def sprite(self) -> tuple[float, float, float, tuple[int, int, int]]:
        return self.x, self.y_int, self.theta, self.shell

    def destroy(self) -> ActionServer | None:
        """Remove every interface; returns the action server when it must outlive this call.

        An active goal is aborted first; its execute coroutine and the client's result request
        finish on later executor turns, so then the action server is handed back to the frame,
        which destroys it a second later (or gives it to a new turtle of the same name).
        """
        deferred = False
        if self.goal is not None:
            goal, self.goal = self.goal, None
            goal.finish(goal.handle.abort)
            deferred = True
        node = self.frame
        node.destroy_subscription(self.cmd_vel_sub)
        node.destroy_publisher(self.pose_pub)
        node.destroy_publisher(self.color_pub)
        for service in self.services:
            node.destroy_service(service)
        if deferred:
            return self.action_server
        self.action_server.destroy()
        return None
