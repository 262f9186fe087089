"""The turtlesim node: canvas, clock/tick, global services and parameters."""

from __future__ import annotations

import json
import math
import re
import sys
import threading
import time
from array import array
from pathlib import Path

from node_runtime.parameter_guard import guard_parameter_services
from node_runtime.rclcpp_parity import RclcppParameters, declare_rclcpp_parameters
from node_runtime.repeat_log import RepeatedLog
from rcl_interfaces.msg import (
    IntegerRange,
    ParameterDescriptor,
    ParameterEvent,
    ParameterType,
    SetParametersResult,
)
from rclpy.callback_groups import CallbackGroup
from rclpy.exceptions import InvalidParameterTypeException, InvalidParameterValueException
from rclpy.impl.implementation_singleton import rclpy_implementation as _rclpy
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import QoSProfile, qos_profile_sensor_data, qos_profile_services_default
from rclpy.service import Service
from rclpy.service_introspection import ServiceIntrospectionState
from std_srvs.srv import Empty, Trigger
from turtlesim.srv import Kill, Spawn

from turtlesim_py import sim
from turtlesim_py.canvas import Canvas
from turtlesim_py.canvas_stream import CanvasStream
from turtlesim_py.turtle import Turtle

BACKGROUND = (('background_r', 69, 'Red channel of the background color'),
              ('background_g', 86, 'Green channel of the background color'),
              ('background_b', 255, 'Blue channel of the background color'))
INTROSPECTION = {'off': ServiceIntrospectionState.OFF,
                 'disabled': ServiceIntrospectionState.OFF,
                 'metadata': ServiceIntrospectionState.METADATA,
                 'contents': ServiceIntrospectionState.CONTENTS}
# The parameter of ros2/demos' introspection_service (`ros2 service echo` needs it on).
INTROSPECTION_PARAMETER = 'service_configure_introspection'
INTROSPECTION_VALUES = ('disabled', 'metadata', 'contents')
# A turtle name becomes a relative name prefix (`<name>/cmd_vel`): tokens of letters, digits
# and underscores, not starting with a digit, no repeated underscores (ROS name rules).
NAME_TOKEN = r'[A-Za-z_][A-Za-z0-9_]*'
TURTLE_NAME = re.compile(rf'{NAME_TOKEN}(/{NAME_TOKEN})*')
# rmw's RMW_TOPIC_MAX_NAME_LENGTH (255 - 8) for a fully qualified name, and the longest
# name a turtle creates below its own (its action's cancel service).
MAX_FULL_NAME_LENGTH = 247
LONGEST_TURTLE_SUFFIX = 'rotate_absolute/_action/cancel_goal'
PARAMETER_EVENT_QOS = QoSProfile(depth=100, history=qos_profile_sensor_data.history,
                                 reliability=qos_profile_sensor_data.reliability,
                                 durability=qos_profile_sensor_data.durability)

GLOBAL_SERVICE_QOS = QoSProfile(depth=1000, history=qos_profile_services_default.history,
                                reliability=qos_profile_services_default.reliability,
                                durability=qos_profile_services_default.durability)


class PolledByTick(CallbackGroup):
    """Subscriptions the tick takes from itself (every turtle's cmd_vel), once per tick.

    The executor never waits on them: left to it, each cmd_vel message woke the executor,
    which rebuilds its wait set over every entity (about 15 per turtle) at each wake. One
    controller answering every pose cost turtlesim 6 % of a core that way, and 200 turtles
    commanded twice a second most of one. Upstream also applies commands once per tick.
    """

    def can_execute(self, entity) -> bool:
        return False

    def beginning_execution(self, entity) -> bool:
        return False

    def ending_execution(self, entity) -> None:
        pass


def turtle_name_problem(name: str, namespace: str = '/') -> str | None:
    """Why `name` cannot name a turtle in `namespace`, or None when it can."""
    if not TURTLE_NAME.fullmatch(name):
        return ('allowed: letters, digits and underscores in /-separated tokens that do not '
                'start with a digit')
    if '__' in name:
        return 'allowed: no repeated underscores'
    # Every name a turtle creates must fit DDS's topic name limit (rcl refuses longer ones
    # with an exception that used to escape and kill the node).
    longest = f'{namespace.rstrip("/")}/{name}/{LONGEST_TURTLE_SUFFIX}'
    if len(longest) > MAX_FULL_NAME_LENGTH:
        room = MAX_FULL_NAME_LENGTH - (len(longest) - len(name))
        return (f'allowed: at most {room} characters here, got {len(name)} (its longest '
                f'name /.../{LONGEST_TURTLE_SUFFIX} must fit in {MAX_FULL_NAME_LENGTH})')
    return None


def shorten(text: str, keep: int = 60) -> str:
    """`text` for one log line: control characters escaped, long input cut (length said)."""
    cut = text if len(text) <= keep else f'{text[:keep]}...({len(text)} characters)'
    return cut if cut.isprintable() else ''.join(
        c if c.isprintable() else repr(c)[1:-1] for c in cut)


class TurtleFrame(RclcppParameters, Node):
    def __init__(self, *, canvas_png: str = 'turtlesim_canvas.png', fixed_step: bool = False,
                 introspection: str = 'off') -> None:
        super().__init__('turtlesim')
        self.canvas_png = Path(canvas_png).absolute()
        self.fixed_step = fixed_step
        self.introspection = INTROSPECTION[introspection]
        self._introspection_used = False
        # One lock for all simulation state: the tick runs on its own thread (see start()),
        # the executor's callbacks on the spinning thread, the window paints from Qt's.
        self.lock = threading.RLock()
        # Errors met once per message or tick (bad cmd_vel, a failing tick) are rate-limited.
        self.repeated = RepeatedLog(self.get_logger())
        self.canvas = Canvas(self.lock)
        self.polled_by_tick = PolledByTick()
        self._stop = threading.Event()
        self._ticker: threading.Thread | None = None
        self.turtles: dict[str, Turtle] = {}
        self._order: list[Turtle] = []
        self._retired: dict[str, object] = {}  # name -> action server awaiting destruction
        self.id_counter = 0
        self.dirty = True
        self._last_tick: float | None = None
        self.sim_time_ns = 0
        self.tick_costs = array('d')  # seconds of work per tick, for --tick-stats
        self.missed_ticks = 0

        rng = IntegerRange(from_value=0, to_value=255, step=1)
        for name, default, description in BACKGROUND:
            self._declare(name, default, ParameterDescriptor(
                type=ParameterType.PARAMETER_INTEGER, description=description,
                integer_range=[rng]))
        self._declare('holonomic', False, ParameterDescriptor(
            type=ParameterType.PARAMETER_BOOL,
            description='If true, then turtles will be holonomic'))
        self._holonomic = bool(self.get_parameter('holonomic').value)
        # Upstream turtlesim has no introspection parameter (it is demo_nodes_cpp's): declare
        # it only when asked at start, by --service-introspection or an override (-p or a
        # params file), so `ros2 param list/dump` print what Jazzy prints. Once declared, it
        # switches introspection at any time. rclpy keeps the overrides in this attribute only.
        if introspection != 'off' or INTROSPECTION_PARAMETER in self._parameter_overrides:
            self._declare(INTROSPECTION_PARAMETER,
                          'disabled' if introspection == 'off' else introspection,
                          ParameterDescriptor(type=ParameterType.PARAMETER_STRING,
                                              description='Service introspection of every '
                                              'service: disabled, metadata or contents'))
            self.introspection = INTROSPECTION[self.get_parameter(INTROSPECTION_PARAMETER).value]
        self.add_post_set_parameters_callback(self._parameters_set)
        guard_parameter_services(self)
        self.create_subscription(ParameterEvent, '/parameter_events', self._on_parameter_event,
                                 PARAMETER_EVENT_QOS)
        declare_rclcpp_parameters(self, subscribe_parameter_events=False)

        # Deeper request queues than the default 10: a burst of 200 spawn calls sent at once
        # would otherwise lose all but the last few requests inside DDS.
        locked = self.locked
        self.create_service(Empty, 'clear', locked(self._on_clear), qos_profile=GLOBAL_SERVICE_QOS)
        self.create_service(Empty, 'reset', locked(self._on_reset), qos_profile=GLOBAL_SERVICE_QOS)
        self.create_service(Spawn, 'spawn', locked(self._on_spawn), qos_profile=GLOBAL_SERVICE_QOS)
        self.create_service(Kill, 'kill', locked(self._on_kill), qos_profile=GLOBAL_SERVICE_QOS)
        self.create_service(Trigger, '~/_save_canvas', locked(self._on_save_canvas))
        self.clock_pub = None
        if fixed_step:
            from rosgraph_msgs.msg import Clock
            self._clock_msg = Clock()
            self.clock_pub = self.create_publisher(Clock, '/clock', 10)
        for service in self.services:
            self.configure_introspection(service)
        self.canvas_stream = CanvasStream(self)  # hidden ~/_canvas for rqt's Turtlesim page

        self.get_logger().info(
            f'Starting turtlesim with node name {self.get_fully_qualified_name()}')
        self.spawn_turtle('', sim.CENTER, sim.CENTER, 0.0)

    # ---------------------------------------------------------------- ticking
    def locked(self, callback):
        """Wrap an executor callback so it never runs in the middle of a tick."""
        lock = self.lock

        def run(*args):
            with lock:
                return callback(*args)
        return run

    def start(self) -> None:
        """Tick every 16 ms on a dedicated thread.

        A ROS timer in the executor would share the executor's per-wait overhead, which grows
        with the number of entities (about 15 per turtle): with 200 turtles rclpy's wait-set
        rebuilds alone pushed the rate down to ~35 Hz. The thread keeps a steady 62.5 Hz.
        """
        # The executor thread holds the GIL for long stretches of pure Python; a short switch
        # interval lets the tick thread in on time.
        sys.setswitchinterval(0.0005)
        self._ticker = threading.Thread(target=self._tick_loop, name='turtlesim-tick',
                                        daemon=True)
        self._ticker.start()
        self.canvas_stream.start()

    def stop(self) -> None:
        self._stop.set()
        self.canvas_stream.stop()
        if self._ticker is not None:
            self._ticker.join(timeout=2.0)
        # The painter stays open between ticks: close it before Qt tears the canvas down, or
        # the exit crashes ("Cannot destroy paint device that is being painted", SIGSEGV).
        with self.lock:
            self.canvas.end_drawing()

    def _tick_loop(self) -> None:
        period = sim.FIXED_DT
        deadline = time.monotonic()
        while not self._stop.is_set():
            delay = deadline - time.monotonic()
            if delay > 0:
                # A plain sleep: Event.wait costs several times more per wake-up, and a stop
                # request is still seen within one period.
                time.sleep(delay)
                if self._stop.is_set():
                    return
            now = time.monotonic()
            if now - deadline > period:  # late by more than a tick: do not burst to catch up
                deadline = now
            deadline += period
            with self.lock:
                try:
                    self.on_tick()
                except Exception as error:
                    self.repeated.error(('tick', type(error)), f'Tick failed: {error!r}')

    # ---------------------------------------------------------------- helpers
    def configure_introspection(self, service: Service) -> None:
        if self.introspection == ServiceIntrospectionState.OFF and not self._introspection_used:
            return  # never switched on: nothing to switch off
        self._introspection_used = True
        try:
            service.configure_introspection(self.get_clock(), qos_profile_services_default,
                                            self.introspection)
        except _rclpy.RCLError as error:
            # get_type_description is served by rcl itself; its Python type has no support
            # for introspection events.
            self.get_logger().debug(f'No introspection for {service.srv_name}: {error}')

    def now_seconds(self) -> float:
        """Time for the cmd_vel timeout: simulated time with --fixed-step, else ROS time."""
        if self.fixed_step:
            return self.sim_time_ns * 1e-9
        # The clock's own reading, without building an rclpy Time object (called every tick).
        clock = self.get_clock().handle
        with clock:
            return clock.get_now().nanoseconds * 1e-9

    def holonomic(self) -> bool:
        return self._holonomic

    def background(self) -> tuple[int, int, int]:
        return tuple(int(self.get_parameter(name).value) for name, _, _ in BACKGROUND)

    # ---------------------------------------------------------------- parameters
    def _declare(self, name: str, default, descriptor: ParameterDescriptor) -> None:
        """Declare; a bad command-line override (-p name:=value) falls back to the default."""
        try:
            self.declare_parameter(name, default, descriptor)
        except (InvalidParameterValueException, InvalidParameterTypeException):
            self.get_logger().error(f'Ignoring the command-line value of {name}; '
                                    f'using the default {default!r}')
            self.declare_parameter(name, default, descriptor, ignore_override=True)

    def _apply_descriptors(self, parameter_list, descriptors, check_read_only=True):
        # rclpy checks types and ranges here, before any on-set callback, with a terse reason
        # and no log. Validate first so a refusal names the field and the allowed values and
        # is logged as an ERROR; rclpy's own checks still run after ours.
        result = self._validate_parameters(parameter_list)
        if not result.successful:
            return result
        return super()._apply_descriptors(parameter_list, descriptors, check_read_only)

    def _validate_parameters(self, parameters: list[Parameter]) -> SetParametersResult:
        for parameter in parameters:
            reason = None
            if parameter.type_ == Parameter.Type.NOT_SET:
                continue  # `ros2 param delete`: rclpy refuses it for these static parameters
            if parameter.name.startswith('background_'):
                value = parameter.value
                if parameter.type_ != Parameter.Type.INTEGER:
                    reason = (f'parameter {parameter.name} must be an integer in 0..255, '
                              f'got {parameter.type_.name.lower()} {value!r}')
                elif not 0 <= value <= 255:
                    reason = f'parameter {parameter.name} must be an integer in 0..255, got {value}'
            elif parameter.name == INTROSPECTION_PARAMETER and (
                    parameter.type_ != Parameter.Type.STRING
                    or parameter.value not in INTROSPECTION_VALUES):
                reason = (f'parameter {INTROSPECTION_PARAMETER} must be one of '
                          f"{', '.join(INTROSPECTION_VALUES)}, got {parameter.value!r}")
            elif parameter.name == 'holonomic' and parameter.type_ != Parameter.Type.BOOL:
                reason = (f'parameter holonomic must be a bool (true or false), '
                          f'got {parameter.type_.name.lower()} {parameter.value!r}')
            if reason:
                self.get_logger().error(f'Refusing to set {reason}')
                return SetParametersResult(successful=False, reason=reason)
        return SetParametersResult(successful=True)

    def _parameters_set(self, parameters: list[Parameter]) -> None:
        for parameter in parameters:
            if parameter.name == 'holonomic':
                self._holonomic = bool(parameter.value)
            elif parameter.name == INTROSPECTION_PARAMETER:
                with self.lock:
                    self.introspection = INTROSPECTION[parameter.value]
                    for service in self.services:
                        self.configure_introspection(service)

    def _on_parameter_event(self, event: ParameterEvent) -> None:
        if event.node == self.get_fully_qualified_name():
            self.dirty = True

    # ---------------------------------------------------------------- turtles
    def spawn_turtle(self, name: str, x: float, y: float, theta: float) -> str:
        if not name:
            while True:
                self.id_counter += 1
                name = f'turtle{self.id_counter}'
                if name not in self.turtles:
                    break
        elif name in self.turtles:
            self.get_logger().error(f'A turtle named [{name}] already exists')
            return ''
        self.turtles[name] = Turtle(self, name, x, y, theta, self._retired.pop(name, None))
        self._order = [self.turtles[key] for key in sorted(self.turtles)]
        self.dirty = True
        self.get_logger().info(
            f'Spawning turtle [{name}] at x=[{x:f}], y=[{y:f}], theta=[{theta:f}]')
        return name

    def kill_turtle(self, name: str) -> None:
        turtle = self.turtles.pop(name)
        self._order = [self.turtles[key] for key in sorted(self.turtles)]
        server = turtle.destroy()
        if server is not None:
            self._retired[name] = server
            timer = None

            def destroy_later() -> None:
                self.destroy_timer(timer)
                if self._retired.get(name) is server:  # not adopted by a new turtle meanwhile
                    del self._retired[name]
                    server.destroy()

            timer = self.create_timer(1.0, self.locked(destroy_later))
        self.dirty = True

    # ---------------------------------------------------------------- services
    def _on_clear(self, request: Empty.Request, response: Empty.Response) -> Empty.Response:
        self.get_logger().info('Clearing turtlesim.')
        self.canvas.clear()
        self.dirty = True
        return response

    def _on_reset(self, request: Empty.Request, response: Empty.Response) -> Empty.Response:
        self.get_logger().info('Resetting turtlesim.')
        for name in list(self.turtles):
            self.kill_turtle(name)
        self.id_counter = 0
        self.spawn_turtle('', sim.CENTER, sim.CENTER, 0.0)
        self.canvas.clear()
        return response

    def _on_spawn(self, request: Spawn.Request, response: Spawn.Response) -> Spawn.Response:
        response.name = ''
        for field in ('x', 'y', 'theta'):
            value = getattr(request, field)
            if not math.isfinite(value):
                self.get_logger().error(
                    f'Refusing to spawn: {field}={value} is not allowed (allowed: finite numbers)')
                return response
        if request.name:
            problem = turtle_name_problem(request.name, self.get_namespace())
            if problem:
                self.get_logger().error(
                    f"Refusing to spawn: name='{shorten(request.name)}' is not a valid ROS "
                    f'name ({problem})')
                return response
        response.name = self.spawn_turtle(request.name, request.x, request.y, request.theta)
        return response

    def _on_kill(self, request: Kill.Request, response: Kill.Response) -> Kill.Response:
        if request.name in self.turtles:
            self.kill_turtle(request.name)
        else:
            self.get_logger().error(
                f'Tried to kill turtle [{shorten(request.name)}], which does not exist')
        return response

    def _on_save_canvas(self, request: Trigger.Request,
                        response: Trigger.Response) -> Trigger.Response:
        try:
            response.message = self.save_canvas()
            response.success = True
        except OSError as error:
            response.success = False
            response.message = str(error)
        return response

    def composite(self):
        return self.canvas.composite(self.background(), [t.sprite() for t in self._order])

    def save_canvas(self) -> str:
        image = self.composite()
        self.canvas_png.parent.mkdir(parents=True, exist_ok=True)
        if not image.save(str(self.canvas_png), 'PNG'):
            raise OSError(f'could not write {self.canvas_png}')
        return str(self.canvas_png)

    # ---------------------------------------------------------------- tick
    def on_tick(self) -> None:
        started = time.perf_counter()
        if self._last_tick is None:
            self._last_tick = started
            return
        if self.fixed_step:
            dt = sim.FIXED_DT
            self.sim_time_ns += 16_000_000
            stamp = self._clock_msg.clock
            stamp.sec, stamp.nanosec = divmod(self.sim_time_ns, 1_000_000_000)
            self.clock_pub.publish(self._clock_msg)
        else:
            dt = started - self._last_tick
        if started - self._last_tick > 1.5 * sim.FIXED_DT:
            self.missed_ticks += round((started - self._last_tick) / sim.FIXED_DT) - 1
        self._last_tick = started
        now = self.now_seconds()
        canvas = self.canvas
        changed = False
        with canvas.lock:
            for turtle in self._order:
                try:
                    changed = turtle.update(dt, now, canvas) or changed
                except Exception as error:
                    self.repeated.error((turtle.name, 'update', type(error)),
                                        f'Updating turtle [{turtle.name}] failed: {error!r}')
            canvas.flush()
        if changed:
            self.dirty = True
        if len(self.tick_costs) < 1_000_000:
            self.tick_costs.append(time.perf_counter() - started)

    def tick_stats(self) -> dict:
        costs = sorted(self.tick_costs)
        ms = [c * 1000.0 for c in costs]
        return {
            'ticks': len(ms),
            'turtles': len(self.turtles),
            'cost_mean_ms': sum(ms) / len(ms) if ms else 0.0,
            'cost_p50_ms': ms[len(ms) // 2] if ms else 0.0,
            'cost_p99_ms': ms[min(len(ms) - 1, int(len(ms) * 0.99))] if ms else 0.0,
            'cost_max_ms': ms[-1] if ms else 0.0,
            'missed_ticks': self.missed_ticks,
        }

    def write_tick_stats(self, path: str) -> None:
        Path(path).write_text(json.dumps(self.tick_stats(), indent=2) + '\n')
