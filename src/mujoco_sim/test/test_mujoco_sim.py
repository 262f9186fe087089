"""The MuJoCo simulator (mujoco_sim) with the diffbot, driven as a learner drives it: /cmd_vel
in, /odom, ground truth, /scan, /camera/image_raw, /clock out, and its services. One simulator
process serves every test here; each test starts from reset_simulation and steps the paused
physics by a known number of steps, so distances are the physics', not the machine's timing."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
from geometry_msgs.msg import Pose, Twist
from nav_msgs.msg import Odometry
from rclpy.node import Node
from rclpy.parameter import Parameter
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import CameraInfo, Image, Imu, JointState, LaserScan
from std_srvs.srv import Empty
from tf2_msgs.msg import TFMessage

from mujoco_sim_interfaces.srv import DeleteEntity, SpawnEntity, StepSimulation
from ws_testing import RosProcess, TestNode, executable, leased_domain, ros_environment

DT = 0.002  # the worlds' timestep
DELIVERY = 0.3  # s for a /cmd_vel message to reach the paused simulator before it steps


def urdf_text() -> str:
    from ament_index_python.packages import get_package_share_directory
    return (Path(get_package_share_directory('diffbot_description')) / 'urdf' /
            'diffbot.urdf').read_text()


def params_file(path: Path, **values) -> Path:
    import yaml
    path.write_text(yaml.safe_dump({'mujoco_sim': {'ros__parameters': values}}))
    return path


class Sim:
    def __init__(self, probe: TestNode, process: RosProcess) -> None:
        self.probe, self.process = probe, process
        self.clock = probe.collect(Clock, '/clock')
        self.odom = probe.collect(Odometry, '/odom')
        self.truth = probe.collect(Odometry, '/ground_truth/odom')
        self.scans = probe.collect(LaserScan, '/scan')
        self.images = probe.collect(Image, '/camera/image_raw')
        self.infos = probe.collect(CameraInfo, '/camera/camera_info')
        self.imu = probe.collect(Imu, '/imu')
        self.joints = probe.collect(JointState, '/joint_states')
        self.tf = probe.collect(TFMessage, '/tf', 100)
        self.cmd = probe.node.create_publisher(Twist, '/cmd_vel', 10)

    def empty(self, name: str) -> None:
        self.probe.call(Empty, f'/{name}', Empty.Request())

    def step(self, steps: int) -> StepSimulation.Response:
        return self.probe.call(StepSimulation, '/step_simulation',
                               StepSimulation.Request(steps=steps))

    def now(self) -> float:
        """The latest /clock after the simulator's answers so far have been taken in."""
        self.probe.spin_for(0.1)
        stamp = self.clock[-1].clock
        return stamp.sec + stamp.nanosec * 1e-9

    def start_paused(self) -> None:
        """Paused at time 0 with the robot at the origin, standing still."""
        self.empty('pause_physics')
        self.empty('reset_simulation')
        self.probe.spin_until(lambda: self.clock and self.now() == 0.0, 5, 'clock reset to 0')

    def drive(self, linear: float, angular: float, seconds: float) -> None:
        self.cmd.publish(Twist(linear=_vec(linear), angular=_vec(z=angular)))
        self.probe.spin_for(DELIVERY)
        assert self.step(round(seconds / DT)).success

    def spawn(self, name: str, xml: str, x: float, y: float = 0.0,
              z: float = 0.0) -> SpawnEntity.Response:
        pose = Pose()
        pose.position.x, pose.position.y, pose.position.z = x, y, z
        return self.probe.call(SpawnEntity, '/spawn_entity',
                               SpawnEntity.Request(name=name, xml=xml, initial_pose=pose))

    def delete(self, name: str) -> DeleteEntity.Response:
        return self.probe.call(DeleteEntity, '/delete_entity', DeleteEntity.Request(name=name))

    def latest(self, messages: list, after: float):
        """The newest message stamped later than `after` (sim seconds)."""
        self.probe.spin_until(
            lambda: messages and _seconds(messages[-1].header.stamp) > after + 1e-9, 5,
            f'a message stamped after {after}')
        return messages[-1]


def _vec(x: float = 0.0, z: float = 0.0):
    from geometry_msgs.msg import Vector3
    return Vector3(x=float(x), z=float(z))


def _seconds(stamp) -> float:
    return stamp.sec + stamp.nanosec * 1e-9


@pytest.fixture(scope='module')
def sim(tmp_path_factory) -> Sim:
    directory = tmp_path_factory.mktemp('mujoco_sim')
    # The camera at 5 Hz, not 15: rendering is most of a step's cost, and 5 Hz still gives
    # every test a frame.
    params = params_file(directory / 'params.yaml', robot_description=urdf_text(),
                         camera_rate=5.0)
    with leased_domain() as domain:
        env = ros_environment(domain)
        process = RosProcess([executable('mujoco_sim', 'mujoco_sim'), '--ros-args',
                              '--params-file', str(params)], env, directory / 'sim.log')
        probe = TestNode(domain)
        try:
            process.wait_for_output(r'\[mujoco_sim\]: Loaded world .*empty\.xml', timeout=30)
            yield Sim(probe, process)
        finally:
            probe.close()
            assert process.stop() == 0, process.output


def test_use_sim_time_node_sees_the_simulators_clock(sim: Sim) -> None:
    sim.start_paused()
    user = Node('sim_time_user', context=sim.probe.context,
                parameter_overrides=[Parameter('use_sim_time', value=True)])
    sim.probe.executor.add_node(user)
    try:
        # Its /clock subscription is matched once a step's clock reaches it.
        sim.probe.spin_until(lambda: sim.step(1).success and
                             user.get_clock().now().nanoseconds > 0, 10,
                             'the use_sim_time node to receive /clock')
        assert sim.step(500).success
        sim.probe.spin_for(0.2)
        # Paused, so its time is exactly the simulator's /clock, nothing like wall time.
        assert user.get_clock().now().nanoseconds == round(sim.now() * 1e9)
        assert 1.0 <= sim.now() < 2.0
    finally:
        sim.probe.executor.remove_node(user)
        user.destroy_node()


def test_pause_step_and_reset(sim: Sim) -> None:
    sim.start_paused()
    sim.probe.spin_for(0.5)
    assert sim.now() == 0.0  # paused: the clock stands still
    response = sim.step(150)
    assert response.success, response.status_message
    assert sim.now() == pytest.approx(0.3, abs=1e-9)
    refused = sim.step(0)
    assert not refused.success and refused.status_message == 'steps is 0; allowed: 1 to 1000000'
    sim.empty('unpause_physics')
    sim.probe.spin_until(lambda: sim.now() > 0.5, 10, 'the clock to run again')
    running = sim.step(10)
    assert (running.success, running.status_message) == \
        (False, 'physics is running: call pause_physics first')
    seen = len(sim.clock)
    sim.empty('reset_simulation')
    # The reset's clock (0) goes out with the reset, and time runs on from there: look for it
    # among the clocks since, not at the latest one (a loaded machine may run on past 0.3 s).
    sim.probe.spin_until(
        lambda: any(c.clock.sec == 0 and c.clock.nanosec < 300_000_000 for c in sim.clock[seen:]),
        5, 'the clock to go back to 0')
    sim.empty('pause_physics')
    assert 'Simulation reset: time 0, every model at its start' in sim.process.output


def test_one_metre_at_0_2_m_per_s(sim: Sim) -> None:
    sim.start_paused()
    sim.drive(0.2, 0.0, 5.0)
    settling = sim.now()
    sim.drive(0.0, 0.0, 0.5)  # stop and settle
    odom, truth = sim.latest(sim.odom, settling), sim.latest(sim.truth, settling)
    assert odom.pose.pose.position.x == pytest.approx(1.0, abs=0.05)
    assert truth.pose.pose.position.x == pytest.approx(1.0, abs=0.05)
    assert abs(odom.pose.pose.position.y) < 0.01 and abs(truth.pose.pose.position.y) < 0.01
    assert abs(odom.twist.twist.linear.x) < 0.01  # stopped
    # The same pose as odom -> base_footprint on /tf (the URDF's root: robot_state_publisher
    # adds base_footprint -> base_link), stamped like the odometry.
    assert (odom.child_frame_id, truth.child_frame_id) == ('base_footprint', 'base_footprint')
    def transforms() -> list:
        return [t for m in sim.tf for t in m.transforms
                if (t.header.frame_id, t.child_frame_id) == ('odom', 'base_footprint')
                and t.header.stamp == odom.header.stamp]
    sim.probe.spin_until(transforms, 5, "odom -> base_footprint on /tf at the odometry's stamp")
    assert transforms()[0].transform.translation.x == odom.pose.pose.position.x
    # Standing still: the IMU reads gravity upwards; the wheels turned 1 m / 0.035 m.
    imu = sim.latest(sim.imu, settling)
    assert imu.header.frame_id == 'imu_link'
    assert imu.linear_acceleration.z == pytest.approx(9.81, abs=0.05)
    joints = sim.latest(sim.joints, settling)
    assert list(joints.name) == ['left_wheel_joint', 'right_wheel_joint']
    assert joints.position[0] == pytest.approx(1.0 / 0.035, rel=0.05)


def _yaw(pose) -> float:
    q = pose.orientation
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


@pytest.mark.parametrize('angular', [0.3, -0.3])
def test_odometry_turns_as_the_robot_does_when_circling(sim: Sim, angular: float) -> None:
    # Circling at 0.2 m/s and 0.3 rad/s, /odom turned 2.8 % more than the robot (the wheels
    # touched the ground at both edges of their treads, scrubbed, and spun at the start).
    # Its heading may now err by at most 0.5 % of the angle turned, either way round.
    sim.start_paused()
    sim.drive(0.2, angular, 10.0)  # 3 rad: no wrap-around in either yaw
    done = sim.now()
    sim.drive(0.0, 0.0, 0.5)
    odom, truth = sim.latest(sim.odom, done), sim.latest(sim.truth, done)
    turned = _yaw(truth.pose.pose)
    assert abs(turned) == pytest.approx(3.0, abs=0.3) and turned * angular > 0
    error = _yaw(odom.pose.pose) - turned
    assert abs(error) <= 0.005 * abs(turned), \
        f'odom turned {math.degrees(error):+.2f} deg more than the robot\'s {turned:.3f} rad'
    # The circle's radius is 0.67 m: the position agrees too (the start is the same point).
    gap = math.hypot(odom.pose.pose.position.x - truth.pose.pose.position.x,
                     odom.pose.pose.position.y - truth.pose.pose.position.y)
    assert gap < 0.02, gap


def test_scan_reads_a_wall_two_metres_ahead(sim: Sim) -> None:
    sim.start_paused()
    # The lidar sits above base_link's origin: the wall's near face is 2.00 m ahead of it.
    wall = '<body><geom type="box" size="0.05 1 0.5" rgba="0.8 0.8 0.8 1"/></body>'
    assert sim.spawn('wall', wall, x=2.05, z=0.5).success
    try:
        spawned = sim.now()
        sim.step(60)
        scan = sim.latest(sim.scans, spawned)
        assert len(scan.ranges) == 360 and scan.angle_min == pytest.approx(-math.pi)
        assert scan.ranges[180] == pytest.approx(2.0, abs=0.02)  # the centre ray: straight ahead
        assert math.isinf(scan.ranges[0])  # nothing behind in the empty world
    finally:
        assert sim.delete('wall').success


def test_camera_sees_coloured_boxes_where_they_are(sim: Sim) -> None:
    if 'camera disabled' in sim.process.output:
        pytest.skip(sim.process.output.split('camera disabled')[1].splitlines()[0])
    import numpy as np
    sim.start_paused()
    red = '<body><geom type="box" size="0.2 0.2 0.2" rgba="1 0 0 1"/></body>'
    blue = '<body><geom type="box" size="0.1 0.1 0.1" rgba="0 0 1 1"/></body>'
    assert sim.spawn('red_box', red, x=1.2, z=0.2).success
    assert sim.spawn('blue_box', blue, x=1.0, y=0.45, z=0.1).success  # on the robot's left
    try:
        spawned = sim.now()
        sim.step(100)
        image = sim.latest(sim.images, spawned)
        info = sim.latest(sim.infos, spawned)
        assert (image.width, image.height, image.encoding) == (320, 240, 'rgb8')
        assert (info.width, info.height) == (320, 240)
        pixels = np.frombuffer(bytes(image.data), dtype=np.uint8).reshape(240, 320, 3)
        centre = pixels[100:140, 140:180].reshape(-1, 3).mean(axis=0)
        assert centre[0] > 120 and centre[1] < 60 and centre[2] < 60, centre
        blue_pixels = (pixels[:, :, 2] > 120) & (pixels[:, :, 0] < 60) & (pixels[:, :, 1] < 60)
        columns = np.nonzero(blue_pixels)[1]
        assert columns.size > 100 and columns.max() < 140, columns  # left of the image
    finally:
        assert sim.delete('red_box').success and sim.delete('blue_box').success


def test_collision_stops_the_robot(sim: Sim) -> None:
    sim.start_paused()
    wall = '<body><geom type="box" size="0.05 1 0.25"/></body>'
    assert sim.spawn('wall', wall, x=0.55, z=0.25).success  # near face at x = 0.50
    try:
        sim.drive(0.3, 0.0, 2.0)  # 0.6 m if nothing were in the way
        truth = sim.latest(sim.truth, sim.now() - 0.1)
        # The camera, the robot's front, is 0.10 m ahead of base_link: it stops at 0.40.
        assert 0.35 < truth.pose.pose.position.x < 0.41
        sim.drive(0.0, 0.0, 0.1)
    finally:
        assert sim.delete('wall').success


def test_bad_input_gets_one_line_and_the_simulation_goes_on(sim: Sim) -> None:
    sim.start_paused()
    for _ in range(5):
        sim.cmd.publish(Twist(linear=_vec(float('nan'))))
    sim.cmd.publish(Twist(linear=_vec(1e9)))
    sim.probe.spin_for(DELIVERY)
    sim.process.wait_for_output(r'clamping /cmd_vel')
    output = sim.process.output
    assert output.count('ignoring /cmd_vel: linear.x is nan; allowed: finite numbers') == 1
    assert ('clamping /cmd_vel (linear.x 1e+09, angular.z 0) to the limits |linear.x| <= 1 m/s'
            in output)
    assert sim.step(100).success and sim.now() == pytest.approx(0.2)
    sim.drive(0.0, 0.0, 0.01)
    ghost = sim.delete('ghost')
    assert not ghost.success and ghost.status_message == "no model named 'ghost' (models: none)"
    broken = sim.spawn('broken', '<body><geom type="box"', x=1.0)
    assert not broken.success and broken.status_message.startswith(
        "model 'broken': xml is not valid XML")
    # A URDF is checked as robot_state_publisher checks the robot's own.
    robot = sim.spawn('robot2', '<robot name="r"><joint name="j" type="fixed"><parent link="a"/>'
                      '<child link="b"/></joint><link name="a"/></robot>', x=1.0)
    assert (robot.success, robot.status_message) == \
        (False, "model 'robot2': child link [b] of joint [j] not found")
    assert sim.process.popen.poll() is None


@pytest.mark.parametrize('values, message', [
    ({'world': '/nonexistent/world.xml'}, r"world file '/nonexistent/world\.xml' does not exist"),
    ({'real_time_factor': 'fast'},
     r"real_time_factor is 'fast'; allowed: a number from 0 to 1000"),
])
def test_bad_world_or_parameter_exits_with_one_line(values, message, tmp_path: Path) -> None:
    params = params_file(tmp_path / 'params.yaml', robot_description=urdf_text(), **values)
    with leased_domain() as domain:
        process = RosProcess([executable('mujoco_sim', 'mujoco_sim'), '--ros-args',
                              '--params-file', str(params)], ros_environment(domain),
                             tmp_path / 'sim.log')
        assert process.wait(timeout=30) == 1
        lines = process.output.strip().splitlines()
        process.stop()
    assert len(lines) == 1, lines
    assert re.fullmatch(r'\[ERROR\] \[[\d.]+\] \[mujoco_sim\]: ' + message, lines[0]), lines
