"""Drive turtle1 around the canvas clear of the walls; pen red on the left, green on the right.

For every Pose on /turtle1/pose it publishes one Twist on /turtle1/cmd_vel, and it calls
/turtle1/set_pen only when the turtle changes side of `boundary_x` (or when the pen it set
was lost: a new turtlesim, a reset, a server that went away). The decisions themselves live
in turtle_logic (plain functions, unit-tested without ROS).
"""

from __future__ import annotations

import sys
import time
from dataclasses import asdict

from geometry_msgs.msg import Twist
from node_runtime.parameter_guard import guard_parameter_services
from node_runtime.spinning import ros_session, spin_until_stopped
from rcl_interfaces.msg import (
    FloatingPointRange,
    IntegerRange,
    ParameterDescriptor,
    ParameterType,
    ParameterValue,
    SetParametersResult,
)
from rclpy.experimental.events_executor import EventsExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from rclpy.task import Future
from turtlesim.msg import Pose
from turtlesim.srv import SetPen

from my_robot_controller.turtle_logic import (
    DEFAULTS,
    PARAMETERS,
    ControllerConfig,
    Rgb,
    Side,
    check_parameters,
    colour_for,
    colour_name,
    pen_call_due,
    side_of,
    velocity_for,
    with_changes,
)

# turtlesim's own QoS for turtle topics: a best-effort or transient-local endpoint would not
# match it (or would replay stale poses).
TURTLE_QOS = QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=7,
                        reliability=ReliabilityPolicy.RELIABLE,
                        durability=DurabilityPolicy.VOLATILE)
POSE_TOPIC = '/turtle1/pose'
SET_PEN_SERVICE = '/turtle1/set_pen'
# How often the ROS graph is checked for the set_pen server and for a new turtle. 5 Hz keeps
# the re-apply after a turtlesim restart well within 1 s; 20 Hz cost 2 % of a core.
GRAPH_CHECK_PERIOD = 0.2
WAITING_WARN_PERIOD = 1.0
# A request unanswered for this long is assumed lost (its server died before answering, or
# the request went out before a just-restarted server had matched us) and is sent again.
PEN_REPLY_TIMEOUT = 2.0


class ParameterError(ValueError):
    pass


class TurtleController(Node):
    def __init__(self) -> None:
        super().__init__('turtle_controller')
        self.config = self._declare_parameters()
        self.add_pre_set_parameters_callback(self.on_parameters_arriving)
        self.add_on_set_parameters_callback(self.on_parameters_proposed)
        self.add_post_set_parameters_callback(self.on_parameters_changed)
        guard_parameter_services(self)  # a request with a bad type byte must not stop us

        self.current_side: Side | None = None     # side of the latest pose
        self.requested_side: Side | None = None   # side whose colour was last asked for
        self.server_ready = False
        # The first warning only after a period: discovery normally takes a moment.
        self.last_waiting_warn = time.monotonic()
        self.pose_publishers: set[bytes] = set()  # GIDs of the /turtle1/pose publishers
        self.pending: dict[Future, tuple[Side, Rgb, float]] = {}  # -> side, colour, time sent

        self.cmd_vel = self.create_publisher(Twist, '/turtle1/cmd_vel', TURTLE_QOS)
        self.create_subscription(Pose, POSE_TOPIC, self.on_pose, TURTLE_QOS)
        self.set_pen = self.create_client(SetPen, SET_PEN_SERVICE)
        self.create_timer(GRAPH_CHECK_PERIOD, self.on_graph_check)
        self.get_logger().info(
            f'driving turtle1: pen {colour_name(self.config.left_colour)} for '
            f'x < {self.config.boundary_x:g}, {colour_name(self.config.right_colour)} from there')

    # --- parameters ------------------------------------------------------------------------
    def _declare_parameters(self) -> ControllerConfig:
        """Declare every parameter with its range; raise ParameterError on bad start values.

        Declared dynamically typed first, so that a bad override ('width:=0', 'boundary_x:=6')
        is reported in our words instead of as an rclpy exception, then pinned to its type
        and range (which `ros2 param describe` shows and rclpy enforces at runtime).
        """
        given = {}
        for name in PARAMETERS:
            default = getattr(DEFAULTS, name)
            value = self.declare_parameter(
                name, default, ParameterDescriptor(dynamic_typing=True)).value
            given[name] = value
        config = with_changes(DEFAULTS, given)
        problems = check_parameters(config)
        if problems:
            raise ParameterError('; '.join(problems))
        for name, value in asdict(config).items():
            self.set_descriptor(name, self._descriptor(name), _parameter_value(value))
        return config

    @staticmethod
    def _descriptor(name: str) -> ParameterDescriptor:
        spec = PARAMETERS[name]
        descriptor = ParameterDescriptor(name=name, description=spec.description)
        if isinstance(getattr(DEFAULTS, name), int):
            descriptor.type = ParameterType.PARAMETER_INTEGER
            descriptor.integer_range = [
                IntegerRange(from_value=int(spec.low), to_value=int(spec.high), step=1)]
        else:
            descriptor.type = ParameterType.PARAMETER_DOUBLE
            descriptor.floating_point_range = [
                FloatingPointRange(from_value=spec.low, to_value=spec.high, step=0.0)]
        return descriptor

    def on_parameters_arriving(self, parameters: list[Parameter]) -> list[Parameter]:
        # 'ros2 param set /turtle_controller boundary_x 6' sends an integer: take it as 6.0
        # rather than refusing it for its type.
        return [Parameter(p.name, Parameter.Type.DOUBLE, float(p.value))
                if p.type_ == Parameter.Type.INTEGER and p.name in PARAMETERS
                and isinstance(getattr(DEFAULTS, p.name), float) else p
                for p in parameters]

    def on_parameters_proposed(self, parameters: list[Parameter]) -> SetParametersResult:
        # Ranges were already enforced by the descriptors; this also catches the rules that
        # involve two parameters (wall_margin_low < wall_margin_high).
        changes = {p.name: p.value for p in parameters if p.name in PARAMETERS}
        problems = check_parameters(with_changes(self.config, changes))
        if problems:
            reason = '; '.join(problems)
            self.get_logger().error(f'parameter change refused: {reason}')
            return SetParametersResult(successful=False, reason=reason)
        return SetParametersResult(successful=True)

    def on_parameters_changed(self, parameters: list[Parameter]) -> None:
        changes = {p.name: p.value for p in parameters if p.name in PARAMETERS}
        old = self.config
        self.config = with_changes(old, changes)
        self.get_logger().info(
            'parameters changed: ' + ', '.join(f'{k}={v}' for k, v in sorted(changes.items())))
        if (old.left_colour, old.right_colour, old.pen_width) != (
                self.config.left_colour, self.config.right_colour, self.config.pen_width):
            self.requested_side = None  # the pen on the turtle is no longer what we want
        if self.current_side is not None:
            self.request_pen_if_due()

    # --- driving ---------------------------------------------------------------------------
    def on_pose(self, pose: Pose) -> None:
        linear, angular = velocity_for(pose.x, pose.y, self.config)
        twist = Twist()
        twist.linear.x = linear
        twist.angular.z = angular
        self.cmd_vel.publish(twist)
        self.current_side = side_of(pose.x, self.config.boundary_x)
        self.request_pen_if_due()

    # --- pen -------------------------------------------------------------------------------
    def request_pen_if_due(self) -> None:
        """Ask for the current side's colour if it is not the one last asked for. Never waits."""
        if not pen_call_due(self.requested_side, self.current_side):
            return
        # Asked live rather than from the last graph check, so that a server found since
        # costs no extra check period (service_is_ready only reads the local graph cache).
        if not self.check_server():
            return
        if self.requested_side is None:
            # A re-apply covers every turtle1 publishing now: the graph check must not take
            # the one whose pose brought us here for yet another new turtle.
            self.pose_publishers = self.pose_publisher_ids()
        side = self.current_side
        r, g, b = colour_for(side, self.config)
        future = self.set_pen.call_async(
            SetPen.Request(r=r, g=g, b=b, width=self.config.pen_width, off=0))
        self.requested_side = side
        self.pending[future] = (side, (r, g, b), time.monotonic())
        future.add_done_callback(self.on_pen_reply)

    def pose_publisher_ids(self) -> set[bytes]:
        return {bytes(info.endpoint_gid)
                for info in self.get_publishers_info_by_topic(POSE_TOPIC)}

    def check_server(self) -> bool:
        """Whether set_pen is served; when that changes, what was asked before no longer holds."""
        ready = self.set_pen.service_is_ready()
        if ready != self.server_ready:
            self.server_ready = ready
            self.requested_side = None
            if ready:
                self.get_logger().info(f'{SET_PEN_SERVICE} is available')
            else:
                self.current_side = None  # a turtle that comes back may be a new one elsewhere
        return ready

    def on_pen_reply(self, future: Future) -> None:
        if future not in self.pending or future.cancelled():
            return  # given up on in on_graph_check
        side, colour, _ = self.pending.pop(future)
        error = future.exception()
        if error is not None:
            self.get_logger().error(f'set_pen for the {side.value} side failed: {error}')
            if self.requested_side is side:
                self.requested_side = None  # try again at the next pose
            return
        self.get_logger().info(f'pen colour applied: {colour_name(colour)} ({side.value} side)')

    def on_graph_check(self) -> None:
        """Track the set_pen server and the turtle's identity; re-apply the pen when lost.

        A restarted turtlesim (or a /reset, or kill + spawn of turtle1) creates a new turtle
        whose pen is the default (179, 184, 255). The reliable sign of that is a new publisher
        endpoint (GID) on /turtle1/pose: each turtle instance owns its own publisher. The
        set_pen server count alone is not enough: a killed process's endpoints stay in the
        graph until their DDS lease expires, so "0 -> 1 servers" may never be observed, and a
        quick /reset replaces the server between two checks. Gaps in the pose stream are not
        enough either: a busy turtlesim pauses without losing its pen.
        """
        if not self.check_server():
            now = time.monotonic()
            if now - self.last_waiting_warn >= WAITING_WARN_PERIOD:
                self.last_waiting_warn = now
                self.get_logger().warning(
                    f'{SET_PEN_SERVICE} not available, waiting (still driving)...')

        publishers = self.pose_publisher_ids()
        if publishers - self.pose_publishers:
            if self.pose_publishers:
                self.get_logger().info('a new turtle1 appeared: applying the pen again')
            # Its side is known from its first pose on: not the side of the old turtle.
            self.requested_side = self.current_side = None
        self.pose_publishers = publishers

        for future, (side, _, sent) in list(self.pending.items()):
            if time.monotonic() - sent > PEN_REPLY_TIMEOUT:
                del self.pending[future]
                self.set_pen.remove_pending_request(future)
                future.cancel()
                self.get_logger().warning(
                    f'set_pen for the {side.value} side unanswered after '
                    f'{PEN_REPLY_TIMEOUT:g} s, asking again')
                if self.requested_side is side:
                    self.requested_side = None
        self.request_pen_if_due()


def _parameter_value(value: int | float) -> ParameterValue:
    if isinstance(value, int):
        return ParameterValue(type=ParameterType.PARAMETER_INTEGER, integer_value=value)
    return ParameterValue(type=ParameterType.PARAMETER_DOUBLE, double_value=value)


def main(args: list[str] | None = None) -> int:
    with ros_session(args) as stop:
        try:
            node = TurtleController()
        except ParameterError as error:
            print(f'turtle_controller: error: {error}', file=sys.stderr)
            return 2
        # rclpy's EventsExecutor (C++) instead of the default SingleThreadedExecutor, which
        # rebuilds its wait set in Python at every wake-up: 62.5 poses a second cost
        # the controller about 3 % of a core more that way (bench/cpu.py).
        spin_until_stopped(node, stop, EventsExecutor())
    return 0


if __name__ == '__main__':
    sys.exit(main())
