"""The robot's side of the bridge: wheel motors from /cmd_vel, and odometry, TF, joint states
and sensors out, in the manner of ros_gz's diff-drive, IMU, lidar and camera bridges."""

from __future__ import annotations

import math
import os

from builtin_interfaces.msg import Time
from geometry_msgs.msg import TransformStamped
from nav_msgs.msg import Odometry as OdometryMsg
from rclpy.node import Node
from sensor_msgs.msg import CameraInfo, Image, Imu, JointState, LaserScan
from tf2_ros import TransformBroadcaster

from mujoco_sim.diff_drive import Odometry, WheelGeometry, wheel_speeds
from mujoco_sim.params import Parameters
from mujoco_sim.sensors import EGL_PACKAGES, Camera, ImuSensor, Lidar
from mujoco_sim.world import RobotSpec, World


def stamp(seconds: float) -> Time:
    """A sim time in seconds as a message stamp (exact to the nanosecond)."""
    nanoseconds = round(seconds * 1e9)
    return Time(sec=nanoseconds // 1_000_000_000, nanosec=nanoseconds % 1_000_000_000)


def _yaw_quaternion(yaw: float) -> tuple[float, float, float, float]:
    return 0.0, 0.0, math.sin(yaw / 2), math.cos(yaw / 2)


class RobotBridge:
    def __init__(self, node: Node, p: Parameters, world: World, spec: RobotSpec) -> None:
        self.node, self.world, self.spec = node, world, spec
        self.rates = {name: p.number(f'{name}_rate', default, 0.01, 1000.0) for name, default
                      in (('odom', 50.0), ('joint_states', 30.0), ('imu', 100.0),
                          ('scan', 10.0), ('camera', 15.0))}
        self.odom_frame = p.text('odom_frame', 'odom')
        self.base_frame = world.robot_body.get('name')
        lidar_frame = p.text('lidar_frame', 'lidar_link')
        range_min = p.number('range_min', 0.12, 0.0, 1000.0)
        self.lidar = Lidar(world.model, lidar_frame, lidar_frame,
                           p.number('scan_samples', 360, 1, 10000, integer=True), range_min,
                           p.number('range_max', 12.0, range_min, 1000.0), self.rates['scan'])
        self.imu = ImuSensor(world.model, spec.imu_link)
        self.camera: Camera | None = None
        self.camera_wanted = p.flag('camera', True)
        self.odom_pub = node.create_publisher(OdometryMsg, 'odom', 10)
        self.truth_pub = node.create_publisher(OdometryMsg, 'ground_truth/odom', 10)
        self.joints_pub = node.create_publisher(JointState, 'joint_states', 10)
        self.imu_pub = node.create_publisher(Imu, 'imu', 10)
        self.scan_pub = node.create_publisher(LaserScan, 'scan', 10)
        self.image_pub = node.create_publisher(Image, 'camera/image_raw', 10)
        self.info_pub = node.create_publisher(CameraInfo, 'camera/camera_info', 10)
        self.tf = TransformBroadcaster(node)
        self.command = (0.0, 0.0)
        self.bind()
        self.odometry = Odometry(self.geometry)
        self.reset()

    def bind(self) -> None:
        """Indices into the (re)compiled model: wheels, motors, the robot's joints, sensors."""
        model = self.world.model
        left, right = self.spec.wheels
        try:
            wheels = [model.joint(name) for name in (left, right)]
        except KeyError:
            raise ValueError(f"left_wheel_joint '{left}' and right_wheel_joint '{right}' must "
                             'be joints of the robot') from None
        self.wheel_qpos = [int(j.qposadr[0]) for j in wheels]
        self.wheel_dof = [int(j.dofadr[0]) for j in wheels]
        self.motors = [model.actuator(f'{name}_motor').id for name in (left, right)]
        bodies = [int(j.bodyid[0]) for j in wheels]
        radius = float(model.geom_size[model.body_geomadr[bodies[0]]][0])
        separation = abs(float(model.body_pos[bodies[0]][1] - model.body_pos[bodies[1]][1]))
        self.geometry = WheelGeometry(radius, separation)
        robot_joints = [j.get('name') for j in self.world.robot_body.iter('joint')]
        self.joints = [(name, int(model.joint(name).qposadr[0]), int(model.joint(name).dofadr[0]))
                       for name in robot_joints]
        self.base_body = model.body(self.base_frame).id
        self.drive(*self.command)

    def start_camera(self) -> bool:
        """Open the offscreen renderer (0.4-0.9 s here: the caller does it after the first
        scan is out, not before). False, with one line naming the fix, when EGL fails."""
        self.camera_wanted = False
        try:
            self.camera = Camera(self.world.model, self.spec.camera_link, *self.spec.image_size,
                                 self.spec.camera_fovy_deg)
        except Exception as error:  # EGL missing or unusable: everything else still runs
            self.node.get_logger().warn(
                f"camera disabled: offscreen rendering (MUJOCO_GL={os.environ['MUJOCO_GL']}) "
                f"failed: {' '.join(str(error).split())} -- install the Debian packages "
                f'{EGL_PACKAGES}')
            return False
        return True

    def rebind(self, world: World) -> None:
        self.world = world
        self.bind()
        self.lidar.bind(world.model, self.lidar.msg.header.frame_id)
        self.imu.bind(world.model)
        if self.camera is not None:
            self.camera.bind(world.model)

    def reset(self) -> None:
        self.drive(0.0, 0.0)
        qpos = self.world.data.qpos
        self.odometry.reset(qpos[self.wheel_qpos[0]], qpos[self.wheel_qpos[1]])
        self.last_time = self.world.data.time

    def drive(self, linear: float, angular: float) -> None:
        self.command = (linear, angular)
        left, right = wheel_speeds(self.geometry, linear, angular)
        self.world.data.ctrl[self.motors[0]] = left
        self.world.data.ctrl[self.motors[1]] = right

    def integrate_odometry(self) -> None:
        data = self.world.data
        self.odometry.update(data.qpos[self.wheel_qpos[0]], data.qpos[self.wheel_qpos[1]],
                             data.time - self.last_time)
        self.last_time = data.time

    def _stamp(self) -> Time:
        return stamp(self.world.data.time)

    def publish_odometry(self) -> None:
        now = self._stamp()
        o = self.odometry
        msg = OdometryMsg()
        msg.header.stamp, msg.header.frame_id = now, self.odom_frame
        msg.child_frame_id = self.base_frame
        msg.pose.pose.position.x, msg.pose.pose.position.y = o.x, o.y
        q = msg.pose.pose.orientation
        q.x, q.y, q.z, q.w = _yaw_quaternion(o.yaw)
        msg.twist.twist.linear.x, msg.twist.twist.angular.z = o.linear, o.angular
        self.odom_pub.publish(msg)
        transform = TransformStamped()
        transform.header = msg.header
        transform.child_frame_id = self.base_frame
        transform.transform.translation.x, transform.transform.translation.y = o.x, o.y
        transform.transform.rotation = msg.pose.pose.orientation
        self.tf.sendTransform(transform)
        # Ground truth: where the simulator has the base, in the world frame.
        data = self.world.data
        truth = OdometryMsg()
        truth.header.stamp, truth.header.frame_id = now, 'world'
        truth.child_frame_id = self.base_frame
        position = data.xpos[self.base_body]
        w, x, y, z = data.xquat[self.base_body]
        pose = truth.pose.pose
        pose.position.x, pose.position.y, pose.position.z = (float(v) for v in position)
        pose.orientation.w, pose.orientation.x = float(w), float(x)
        pose.orientation.y, pose.orientation.z = float(y), float(z)
        velocity = data.cvel[self.base_body]  # angular then linear, at the subtree's centre
        truth.twist.twist.angular.z = float(velocity[2])
        self.truth_pub.publish(truth)

    def publish_joint_states(self) -> None:
        data = self.world.data
        msg = JointState()
        msg.header.stamp = self._stamp()
        msg.name = [name for name, _, _ in self.joints]
        msg.position = [float(data.qpos[q]) for _, q, _ in self.joints]
        msg.velocity = [float(data.qvel[v]) for _, _, v in self.joints]
        self.joints_pub.publish(msg)

    def publish_imu(self) -> None:
        self.imu_pub.publish(self.imu.read(self.world.data, self._stamp()))

    def publish_scan(self) -> None:
        self.scan_pub.publish(self.lidar.scan(self.world.model, self.world.data, self._stamp()))

    def publish_camera(self) -> None:
        image, info = self.camera.capture(self.world.data, self._stamp())
        self.image_pub.publish(image)
        self.info_pub.publish(info)
