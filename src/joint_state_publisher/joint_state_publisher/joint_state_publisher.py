"""joint_state_publisher: /joint_states for every movable joint of the robot description.

As upstream (ros/joint_state_publisher, ros2 branch): node `joint_state_publisher`, the
description from /robot_description (transient local) or a URDF file given as argument;
parameters `rate` (10), `publish_default_positions/velocities/efforts`, `use_mimic_tags`,
`use_smallest_joint_limits`, `source_list`, `delta`, `zeros.<joint>`,
`dependent_joints.<joint>.parent/factor/offset`. A joint starts at `zeros.<joint>`, else 0
when 0 is within its limits, else at the centre of its limits; mimic joints follow their
joint (multiplier, offset); messages on the `source_list` topics overwrite the positions.

On purpose unlike upstream: a bad description or a mimic loop is one logged line, the node
keeps running with the last good joints (upstream raises or exits). URDF only (no SDF/COLLADA).
"""

from __future__ import annotations

import math
import sys
import xml.etree.ElementTree as ET
from collections.abc import Callable
from dataclasses import dataclass

import rclpy
from node_runtime.spinning import ros_session, spin_until_stopped
from rcl_interfaces.msg import ParameterDescriptor, ParameterType
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, QoSProfile
from sensor_msgs.msg import JointState
from std_msgs.msg import String

DEFAULTS = {'publish_default_efforts': (False, ParameterType.PARAMETER_BOOL),
            'publish_default_positions': (True, ParameterType.PARAMETER_BOOL),
            'publish_default_velocities': (False, ParameterType.PARAMETER_BOOL),
            'rate': (10, ParameterType.PARAMETER_INTEGER),
            'source_list': ([], ParameterType.PARAMETER_STRING_ARRAY),
            'use_mimic_tags': (True, ParameterType.PARAMETER_BOOL),
            'use_smallest_joint_limits': (True, ParameterType.PARAMETER_BOOL),
            'delta': (0.0, ParameterType.PARAMETER_DOUBLE)}


class DescriptionError(ValueError):
    """A description without usable joints; str() names the element."""


@dataclass
class FreeJoint:
    lower: float
    upper: float
    position: float
    continuous: bool = False
    velocity: float | None = None
    effort: float | None = None
    forward: bool = True


@dataclass(frozen=True)
class Dependent:
    parent: str
    factor: float = 1.0
    offset: float = 0.0


def _limit(joint: str, kind: str, text: str | None) -> float:
    try:
        value = float(text)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise DescriptionError(f'joint "{joint}": <limit {kind}="{text}"> must be a number') \
            from None
    if not math.isfinite(value):
        raise DescriptionError(f'joint "{joint}": <limit {kind}> must be finite')
    return value


def read_joints(description: str, zeros: dict[str, float], use_mimic: bool,
                use_smallest: bool) -> tuple[dict[str, FreeJoint], list[str],
                                             dict[str, Dependent]]:
    """Free joints, all movable joints in file order, and mimic joints of a URDF."""
    try:
        robot = ET.fromstring(description)
    except ET.ParseError as error:
        raise DescriptionError(f'robot description is not valid XML: {error}') from None
    if robot.tag != 'robot':
        raise DescriptionError(f'URDF must have a "robot" tag, got <{robot.tag}>')
    free: dict[str, FreeJoint] = {}
    order: list[str] = []
    dependent: dict[str, Dependent] = {}
    for joint in robot.findall('joint'):
        kind, name = joint.get('type', ''), joint.get('name', '')
        if kind in ('fixed', 'floating', 'planar'):
            continue
        if kind == 'continuous':
            lower, upper = -math.pi, math.pi
        else:
            limit = joint.find('limit')
            if limit is None:
                raise DescriptionError(
                    f'Limits must be specified for joint "{name}" of type "{kind}"')
            lower = _limit(name, 'lower', limit.get('lower'))
            upper = _limit(name, 'upper', limit.get('upper'))
        safety = joint.find('safety_controller')
        if use_smallest and safety is not None:
            if safety.get('soft_lower_limit') is not None:
                lower = max(lower, _limit(name, 'soft_lower_limit',
                                          safety.get('soft_lower_limit')))
            if safety.get('soft_upper_limit') is not None:
                upper = min(upper, _limit(name, 'soft_upper_limit',
                                          safety.get('soft_upper_limit')))
        order.append(name)
        mimic = joint.find('mimic')
        if use_mimic and mimic is not None:
            dependent[name] = Dependent(
                mimic.get('joint', ''), _limit(name, 'mimic multiplier',
                                               mimic.get('multiplier', '1')),
                _limit(name, 'mimic offset', mimic.get('offset', '0')))
            continue
        if name in zeros:
            start = zeros[name]
        elif lower > 0 or upper < 0:
            start = (lower + upper) / 2
        else:
            start = 0.0
        free[name] = FreeJoint(lower, upper, start, continuous=kind == 'continuous')
    for name, dep in dependent.items():
        chain = [name]
        parent = dep.parent
        while parent in dependent:
            if parent in chain:
                raise DescriptionError('Found an infinite recursive mimic chain: '
                                       f'{[*chain, parent]}')
            chain.append(parent)
            parent = dependent[parent].parent
        if parent not in free:
            raise DescriptionError(f'joint "{name}" mimics joint "{parent}", which is not a '
                                   'movable joint')
    return free, order, dependent


class JointStatePublisher(Node):
    def __init__(self, description_file: str | None) -> None:
        super().__init__('joint_state_publisher',
                         automatically_declare_parameters_from_overrides=True)
        for name, (default, kind) in DEFAULTS.items():
            if not self.has_parameter(name):  # else declared from the overrides already
                self.declare_parameter(name, default, ParameterDescriptor(type=kind))
        self.free: dict[str, FreeJoint] = {}
        self.order: list[str] = []
        self.dependent: dict[str, Dependent] = self.dependent_joints_parameter()
        self.zeros = {k: float(p.value) for k, p in
                      self.get_parameters_by_prefix('zeros').items()}
        if description_file is not None:
            try:
                with open(description_file, encoding='utf-8') as f:
                    self.configure(f.read())
            except OSError as error:
                self.get_logger().error(f'Cannot read {description_file}: {error}')
        else:
            self.get_logger().info('Waiting for robot_description to be published on the '
                                   'robot_description topic...')
        self.create_subscription(
            String, 'robot_description', self.on_robot_description,
            QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL))
        for topic in self.get_parameter('source_list').value:
            if topic:
                self.create_subscription(JointState, topic, self.on_source, 10)
        self.publisher = self.create_publisher(JointState, 'joint_states', 10)
        rate = self.get_parameter('rate').value
        if not isinstance(rate, (int, float)) or not 0 < rate <= 1000:
            self.get_logger().error(f'rate must be a number in (0, 1000], got {rate!r}; '
                                    'using 10')
            rate = 10
        self.create_timer(1.0 / rate, self.on_timer)

    def dependent_joints_parameter(self) -> dict[str, Dependent]:
        found: dict[str, dict] = {}
        for key, p in self.get_parameters_by_prefix('dependent_joints').items():
            joint, _, field = key.rpartition('.')
            found.setdefault(joint, {})[field] = p.value
        return {j: Dependent(str(f.get('parent', '')), float(f.get('factor', 1.0)),
                             float(f.get('offset', 0.0)))
                for j, f in found.items() if 'parent' in f}

    def configure(self, description: str) -> None:
        try:
            free, order, dependent = read_joints(
                description, self.zeros, self.get_parameter('use_mimic_tags').value,
                self.get_parameter('use_smallest_joint_limits').value)
        except DescriptionError as error:
            self.get_logger().error(str(error))
            return
        self.free, self.order = free, order
        self.dependent = {**dependent, **self.dependent_joints_parameter()}

    def on_robot_description(self, msg: String) -> None:
        self.configure(msg.data)

    def on_source(self, msg: JointState) -> None:
        for i, name in enumerate(msg.name):
            joint = self.free.get(name)
            if joint is None:
                continue
            if i < len(msg.position):
                joint.position = msg.position[i]
            if i < len(msg.velocity):
                joint.velocity = msg.velocity[i]
            if i < len(msg.effort):
                joint.effort = msg.effort[i]

    def resolve(self, name: str) -> tuple[FreeJoint, float, float] | None:
        """The free joint `name` follows, with the accumulated factor and offset."""
        factor, offset, seen = 1.0, 0.0, {name}
        while name in self.dependent:
            dep = self.dependent[name]
            offset += factor * dep.offset
            factor *= dep.factor
            name = dep.parent
            if name in seen:
                return None
            seen.add(name)
        joint = self.free.get(name)
        return None if joint is None else (joint, factor, offset)

    def on_timer(self) -> None:
        delta = self.get_parameter('delta').value
        if delta > 0:
            self.step(delta)
        msg = JointState()
        msg.header.stamp = self.get_clock().now().to_msg()
        velocities = any(j.velocity is not None for j in self.free.values()) or \
            self.get_parameter('publish_default_velocities').value
        efforts = any(j.effort is not None for j in self.free.values()) or \
            self.get_parameter('publish_default_efforts').value
        for name in self.order:
            found = self.resolve(name)
            if found is None:
                continue
            joint, factor, offset = found
            msg.name.append(name)
            msg.position.append(joint.position * factor + offset)
            if velocities:
                msg.velocity.append((joint.velocity or 0.0) * factor)
            if efforts:
                msg.effort.append(joint.effort or 0.0)
        if msg.name:
            self.publisher.publish(msg)

    def step(self, delta: float) -> None:
        for joint in self.free.values():
            joint.position += delta if joint.forward else -delta
            if joint.position > joint.upper:
                if joint.continuous:
                    joint.position = joint.lower
                else:
                    joint.position, joint.forward = joint.upper, False
            elif joint.position < joint.lower:
                joint.position, joint.forward = joint.lower, True


def main(args: list[str] | None = None,
         setup: Callable[[JointStatePublisher], None] | None = None) -> None:
    """Run the node until Ctrl-C; `setup` adds to it first (joint_state_publisher_gui's
    slider topic and page)."""
    with ros_session(args) as stop:
        argv = rclpy.utilities.remove_ros_args(args or sys.argv)[1:]
        node = JointStatePublisher(argv[0] if argv else None)
        if setup is not None:
            setup(node)
        spin_until_stopped(node, stop)


if __name__ == '__main__':
    main()
