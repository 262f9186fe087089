"""robot_state_publisher: a URDF on /robot_description, its links' poses on /tf and /tf_static.

As upstream (ros/robot_state_publisher, Jazzy): node `robot_state_publisher`, parameters
`robot_description`, `publish_frequency` (20.0, 0-1000), `frame_prefix`, `ignore_timestamp`;
`/robot_description` is latched (transient local, depth 1); fixed (and planar) joints go to
/tf_static once per description; moving joints go to /tf for each /joint_states message
(sensor-data QoS) with the message's stamp, at most `publish_frequency` times a second per
joint unless `ignore_timestamp`. Mimic joints follow their joint. Floating joints are skipped
(kdl_parser's "Converting unknown joint type" warning is logged for planar and floating joints).
A mesh file that is not on this machine is one warning line naming the link (upstream does not
look at meshes); the description is still used.

On purpose unlike upstream: a bad or empty description does not end the node; it logs one
line naming the element and waits for a valid `robot_description` (set with `ros2 param set`).
"""

from __future__ import annotations

import sys

import rclpy
from geometry_msgs.msg import TransformStamped
from node_runtime.spinning import ros_session, spin_until_stopped
from rcl_interfaces.msg import SetParametersResult
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import DurabilityPolicy, QoSProfile, qos_profile_sensor_data
from rclpy.time import Time
from sensor_msgs.msg import JointState
from std_msgs.msg import String
from tf2_ros import StaticTransformBroadcaster, TransformBroadcaster

from robot_state_publisher.urdf_model import (
    Joint,
    RobotModel,
    UrdfError,
    missing_meshes,
    parse,
)

FREQUENCY_RANGE = (0.0, 1000.0)


class RobotStatePublisher(Node):
    def __init__(self, argv: list[str]) -> None:
        super().__init__('robot_state_publisher')
        self.model: RobotModel | None = None
        self.moving: dict[str, Joint] = {}
        self.last_publish: dict[str, int] = {}  # joint -> stamp (ns) last published
        self.last_callback_ns = 0
        description = self.declare_parameter('robot_description', '').value
        frequency = self.declare_parameter('publish_frequency', 20.0).value
        self.declare_parameter('frame_prefix', '')
        self.declare_parameter('ignore_timestamp', False)
        if not isinstance(frequency, float) or not (
                FREQUENCY_RANGE[0] <= frequency <= FREQUENCY_RANGE[1]):
            self.get_logger().error(f'publish_frequency must be between 0 and 1000, got '
                                    f'{frequency!r}; using 20.0')
            self.set_parameters([Parameter('publish_frequency', value=20.0)])
        if not description and len(argv) > 1:
            description = self.read_urdf_argument(argv[1])
        self.tf_broadcaster = TransformBroadcaster(self)
        self.static_broadcaster = StaticTransformBroadcaster(self)
        self.description_pub = self.create_publisher(
            String, 'robot_description',
            QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL))
        self.setup_urdf(description)
        self.create_subscription(JointState, 'joint_states', self.on_joint_states,
                                 qos_profile_sensor_data)
        self.add_on_set_parameters_callback(self.on_set_parameters)
        self.add_post_set_parameters_callback(self.on_parameters_set)

    def read_urdf_argument(self, path: str) -> str:
        self.get_logger().warn(
            'No robot_description parameter, but command-line argument available.  Assuming '
            'argument is name of URDF file.  This backwards compatibility fallback will be '
            'removed in the future.')
        try:
            with open(path, encoding='utf-8') as f:
                text = f.read()
        except (OSError, UnicodeDecodeError) as error:
            self.get_logger().error(f'Failed to open URDF file: {path}: {error}')
            return ''
        self.set_parameters([Parameter('robot_description', value=text)])
        return text

    def setup_urdf(self, description: str) -> bool:
        try:
            model = parse(description)
        except UrdfError as error:
            self.get_logger().error(f'{error}; waiting for a valid robot_description')
            return False
        self.model, self.moving, self.last_publish = model, model.moving(), {}
        for joint in model.joints:
            if joint.type in ('planar', 'floating'):  # kdl_parser's warning, for both
                self.get_logger().warn(f"Converting unknown joint type of joint "
                                       f"'{joint.name}' into a fixed joint")
            if joint.type == 'floating':
                self.get_logger().debug(
                    f'Floating joint is not supported; skipping segment from {joint.parent} '
                    f'to {joint.child}.')
        for line in missing_meshes(model):  # upstream does not look; rviz2 would fail later
            self.get_logger().warn(line)
        self.description_pub.publish(String(data=description))
        self.publish_fixed_transforms()
        self.get_logger().info('Robot initialized')
        return True

    def make_transform(self, joint: Joint, position: float, stamp) -> TransformStamped:
        prefix = self.get_parameter('frame_prefix').value
        t = TransformStamped()
        t.header.stamp = stamp
        t.header.frame_id = prefix + joint.parent
        t.child_frame_id = prefix + joint.child
        xyz, q = joint.transform(position)
        t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = xyz
        (t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z,
         t.transform.rotation.w) = q
        return t

    def publish_fixed_transforms(self) -> None:
        if self.model is None:
            return
        stamp = self.get_clock().now().to_msg()
        transforms = [self.make_transform(j, 0.0, stamp) for j in self.model.fixed()]
        if transforms:
            self.static_broadcaster.sendTransform(transforms)

    def on_joint_states(self, state: JointState) -> None:
        if len(state.name) != len(state.position):
            if not state.position and state.name:
                self.get_logger().warn(
                    'Robot state publisher ignored a JointState message about joint(s) '
                    f'"{state.name[0]}"(,...) whose position member was empty.')
            else:
                self.get_logger().error(
                    'Robot state publisher ignored an invalid JointState message')
            return
        now_ns = self.get_clock().now().nanoseconds
        if self.last_callback_ns > now_ns:
            self.get_logger().warn('Moved backwards in time, re-publishing joint transforms!')
            self.last_publish.clear()
        self.last_callback_ns = now_ns
        stamp_ns = Time.from_msg(state.header.stamp).nanoseconds
        last = min([self.last_publish.get(name, 0) for name in state.name], default=now_ns)
        frequency = self.get_parameter('publish_frequency').value
        interval_ns = int(1e9 / frequency) if frequency > 0 else 0
        if not (self.get_parameter('ignore_timestamp').value
                or stamp_ns >= last + interval_ns):
            return
        positions = dict(zip(state.name, state.position, strict=False))
        for name, joint in self.moving.items():
            if joint.mimic and joint.mimic.joint in positions and name not in positions:
                positions[name] = (positions[joint.mimic.joint] * joint.mimic.multiplier
                                   + joint.mimic.offset)
        transforms = [self.make_transform(self.moving[name], position, state.header.stamp)
                      for name, position in positions.items() if name in self.moving]
        if transforms:
            self.tf_broadcaster.sendTransform(transforms)
        for name in state.name:
            self.last_publish[name] = stamp_ns

    def on_set_parameters(self, parameters: list[Parameter]) -> SetParametersResult:
        for p in parameters:
            if p.name == 'robot_description':
                if p.type_ != Parameter.Type.STRING or not p.value:
                    return SetParametersResult(successful=False,
                                               reason='Empty URDF is not allowed')
                try:
                    parse(p.value)
                except UrdfError as error:
                    self.get_logger().warn(str(error))
                    return SetParametersResult(successful=False, reason=str(error))
            elif p.name == 'publish_frequency' and (
                    p.type_ != Parameter.Type.DOUBLE
                    or not FREQUENCY_RANGE[0] <= p.value <= FREQUENCY_RANGE[1]):
                return SetParametersResult(
                    successful=False, reason='publish_frequency must be between 0.0 and 1000.0')
            elif p.name == 'frame_prefix' and p.type_ != Parameter.Type.STRING:
                return SetParametersResult(successful=False,
                                           reason='frame_prefix must be a string')
            elif p.name == 'ignore_timestamp' and p.type_ != Parameter.Type.BOOL:
                return SetParametersResult(successful=False,
                                           reason='ignore_timestamp must be a bool')
        return SetParametersResult(successful=True)

    def on_parameters_set(self, parameters: list[Parameter]) -> None:
        for p in parameters:
            if p.name == 'robot_description' and hasattr(self, 'description_pub'):
                self.setup_urdf(p.value)


def main(args: list[str] | None = None) -> None:
    with ros_session(args) as stop:
        node = RobotStatePublisher(rclpy.utilities.remove_ros_args(args or sys.argv))
        spin_until_stopped(node, stop)


if __name__ == '__main__':
    main()
