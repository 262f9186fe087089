"""`ros2 run mujoco_sim mujoco_sim --ros-args -p robot_description:="$(cat robot.urdf)"
[-p world:=/path/world.xml] [-p real_time_factor:=1.0]`: a MuJoCo world bridged to ROS 2.

Physics steps at the world's fixed timestep, paced to the wall clock times
`real_time_factor` (0: as fast as the CPU allows). Sensors are sampled inside the step loop
when their period in sim time is due, so their stamps are exact sim times; `/clock` carries
the same time for nodes run with use_sim_time:=true. The wall timer only paces.
"""

from __future__ import annotations

import os
import sys

os.environ.setdefault('MUJOCO_GL', 'egl')  # before mujoco loads: headless by default

from node_runtime import quiet_ctrl_c_while_starting

quiet_ctrl_c_while_starting('mujoco_sim')

import time  # noqa: E402
from collections.abc import Callable  # noqa: E402
from pathlib import Path  # noqa: E402

import mujoco  # noqa: E402
from geometry_msgs.msg import Twist  # noqa: E402
from node_runtime.repeat_log import RepeatLimiter, with_count  # noqa: E402
from node_runtime.spinning import ros_session, spin_until_stopped  # noqa: E402
from rclpy.node import Node  # noqa: E402
from rosgraph_msgs.msg import Clock  # noqa: E402
from std_srvs.srv import Empty  # noqa: E402

from mujoco_sim.bridge import RobotBridge, stamp  # noqa: E402
from mujoco_sim.diff_drive import check_twist  # noqa: E402
from mujoco_sim.params import Parameters  # noqa: E402
from mujoco_sim.world import RobotSpec, World, WorldError  # noqa: E402
from mujoco_sim_interfaces.srv import DeleteEntity, SpawnEntity, StepSimulation  # noqa: E402

TICK = 0.01  # s of wall time between two pacing ticks
MAX_LAG = 0.25  # s of sim time the pacing may fall behind before it stops catching up
MAX_STEPS = 1_000_000  # most steps one step_simulation call may ask for


def default_world() -> str:
    from ament_index_python.packages import get_package_share_directory
    return str(Path(get_package_share_directory('mujoco_sim')) / 'worlds' / 'empty.xml')


class Periodic:
    """Something published every `period` seconds of sim time."""

    def __init__(self, period: float, publish: Callable[[], None]) -> None:
        self.period, self.publish, self.due = period, publish, 0.0

    def poll(self, now: float) -> None:
        if now + 1e-9 >= self.due:
            self.publish()
            # The next sample on the period's grid; after a pause or reset, from now on.
            self.due = self.due + self.period if self.due + self.period > now \
                else now + self.period


class MujocoSim(Node):
    def __init__(self) -> None:
        super().__init__('mujoco_sim')
        p = Parameters(self)
        world = p.text('world', '') or default_world()
        urdf = p.text('robot_description', '')
        self.rtf = p.number('real_time_factor', 1.0, 0.0, 1000.0)
        if not urdf.strip():
            raise WorldError("robot_description parameter must not be empty (give the robot's "
                             'URDF, e.g. -p robot_description:="$(cat robot.urdf)")')
        spec = RobotSpec(
            urdf=urdf,
            pose=(p.number('x', 0.0), p.number('y', 0.0), p.number('yaw', 0.0)),
            wheels=(p.text('left_wheel_joint', 'left_wheel_joint'),
                    p.text('right_wheel_joint', 'right_wheel_joint')),
            camera_link=p.text('camera_frame', 'camera_link'),
            camera_fovy_deg=p.number('camera_fov_deg', 60.0, 1.0, 179.0),
            image_size=(p.number('image_width', 320, 1, 4096, integer=True),
                        p.number('image_height', 240, 1, 4096, integer=True)),
            imu_link=p.text('imu_frame', 'imu_link'))
        self.max_linear = p.number('max_linear_velocity', 1.0, 0.0, 100.0)
        self.max_angular = p.number('max_angular_velocity', 4.0, 0.0, 100.0)
        self.world = World(world, spec)
        self.bridge = RobotBridge(self, p, self.world, spec)
        self.clock_pub = self.create_publisher(Clock, 'clock', 10)
        rate = self.bridge.rates
        self.outputs = [Periodic(0.01, self.publish_clock),
                        Periodic(1.0 / rate['odom'], self.bridge.publish_odometry),
                        Periodic(1.0 / rate['joint_states'], self.bridge.publish_joint_states),
                        Periodic(1.0 / rate['imu'], self.bridge.publish_imu),
                        Periodic(1.0 / rate['scan'], self.bridge.publish_scan)]
        self.cmd_warnings = RepeatLimiter()
        self.create_subscription(Twist, 'cmd_vel', self.on_cmd_vel, 10)
        self.create_service(Empty, 'reset_simulation', self.on_reset_simulation)
        self.create_service(Empty, 'reset_world', self.on_reset_world)
        self.create_service(Empty, 'pause_physics', self.on_pause)
        self.create_service(Empty, 'unpause_physics', self.on_unpause)
        self.create_service(StepSimulation, 'step_simulation', self.on_step)
        self.create_service(SpawnEntity, 'spawn_entity', self.on_spawn)
        self.create_service(DeleteEntity, 'delete_entity', self.on_delete)
        self.paused = False
        self.ticks = 0
        self.anchor = (time.monotonic(), self.world.data.time)
        self.create_timer(TICK, self.tick)
        model = self.world.model
        speed = 'as fast as possible' if self.rtf == 0 else f'{self.rtf:g}x real time'
        self.get_logger().info(
            f"Loaded world '{world}' ({model.nbody - 1} bodies) with robot "
            f"'{self.world.robot_name}'; timestep {model.opt.timestep:g} s, "
            f'{speed}')

    # --- stepping --------------------------------------------------------------------------
    def step(self, count: int) -> None:
        model, data = self.world.model, self.world.data
        for _ in range(count):
            mujoco.mj_step(model, data)
            now = data.time
            self.bridge.integrate_odometry()
            for output in self.outputs:
                output.poll(now)

    def tick(self) -> None:
        self.ticks += 1
        if self.bridge.camera_wanted and self.ticks == 2:
            # After the first tick's sensors: starting the renderer does not delay them.
            if self.bridge.start_camera():
                camera = Periodic(1.0 / self.bridge.rates['camera'], self.bridge.publish_camera)
                camera.due = self.world.data.time
                self.outputs.append(camera)
            self.anchor = (time.monotonic(), self.world.data.time)  # its start is not lag
        if self.paused:
            return
        dt = self.world.model.opt.timestep
        if self.rtf == 0:
            # As fast as possible, yet the executor gets to serve callbacks every 20 ms.
            deadline = time.monotonic() + 0.02
            while time.monotonic() < deadline:
                self.step(50)
            return
        wall, sim = self.anchor
        target = sim + (time.monotonic() - wall) * self.rtf
        behind = target - self.world.data.time
        if behind > MAX_LAG:  # too slow for this factor: run as fast as it can from here
            self.anchor = (time.monotonic() - MAX_LAG / self.rtf, self.world.data.time)
            behind = MAX_LAG
        self.step(int(behind / dt + 1e-6))

    def publish_clock(self) -> None:
        self.clock_pub.publish(Clock(clock=stamp(self.world.data.time)))

    def restart_outputs(self) -> None:
        for output in self.outputs:
            output.due = self.world.data.time
        self.anchor = (time.monotonic(), self.world.data.time)

    # --- topics and services ---------------------------------------------------------------
    def on_cmd_vel(self, msg: Twist) -> None:
        linear, angular, warning = check_twist(msg.linear.x, msg.angular.z, self.max_linear,
                                               self.max_angular)
        if warning:
            suppressed = self.cmd_warnings.admit(warning.split(' (')[0].split(':')[0])
            if suppressed is not None:
                self.get_logger().warn(with_count(warning, suppressed))
        self.bridge.drive(linear, angular)

    def _reset(self, keep_time: bool) -> None:
        self.world.reset(keep_time)
        self.bridge.reset()
        self.restart_outputs()
        self.step(0)
        for output in self.outputs:  # the reset state at once (clock, odom, scan, ...)
            output.poll(self.world.data.time)

    def on_reset_simulation(self, _request, response):
        self._reset(keep_time=False)
        self.get_logger().info('Simulation reset: time 0, every model at its start')
        return response

    def on_reset_world(self, _request, response):
        self._reset(keep_time=True)
        self.get_logger().info('World reset: every model at its start, time goes on')
        return response

    def on_pause(self, _request, response):
        self.paused = True
        return response

    def on_unpause(self, _request, response):
        self.paused = False
        self.ticks = 0
        self.anchor = (time.monotonic(), self.world.data.time)
        return response

    def on_step(self, request, response):
        if not self.paused:
            response.success = False
            response.status_message = 'physics is running: call pause_physics first'
        elif not 1 <= request.steps <= MAX_STEPS:
            response.success = False
            response.status_message = f'steps is {request.steps}; allowed: 1 to {MAX_STEPS}'
        else:
            self.step(request.steps)
            self.publish_clock()
            response.success = True
            response.status_message = f'stepped to t={self.world.data.time:.6f} s'
        if not response.success:
            self.get_logger().warn(f'step_simulation refused: {response.status_message}')
        return response

    def _change_models(self, what: str, change: Callable[[], None], response):
        try:
            change()
        except WorldError as error:
            response.success, response.status_message = False, str(error)
            self.get_logger().warn(f'{what} refused: {error}')
            return response
        self.bridge.rebind(self.world)
        response.success, response.status_message = True, ''
        return response

    def on_spawn(self, request, response):
        def change() -> None:
            if request.reference_frame not in ('', 'world'):
                raise WorldError(f"reference_frame is '{request.reference_frame}'; allowed: "
                                 "'' or 'world'")
            self.world.spawn(request.name, request.xml, request.initial_pose.position,
                             request.initial_pose.orientation)
        self._change_models('spawn_entity', change, response)
        if response.success:
            response.status_message = f"spawned '{request.name}'"
            self.get_logger().info(f"Spawned model '{request.name}'")
        return response

    def on_delete(self, request, response):
        self._change_models('delete_entity', lambda: self.world.delete(request.name), response)
        if response.success:
            response.status_message = f"deleted '{request.name}'"
            self.get_logger().info(f"Deleted model '{request.name}'")
        return response


def main() -> int:
    with ros_session() as stop:
        try:
            node = MujocoSim()
        except (WorldError, ValueError) as error:
            from rclpy.logging import get_logger
            get_logger('mujoco_sim').error(str(error))
            return 1
        spin_until_stopped(node, stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
