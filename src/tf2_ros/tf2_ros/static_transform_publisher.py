"""ros2 run tf2_ros static_transform_publisher: publish one static transform until stopped.

Arguments as upstream's: --x --y --z, --qx --qy --qz --qw or --roll --pitch --yaw,
--frame-id, --child-frame-id; or the deprecated positional forms
`x y z yaw pitch roll frame child` and `x y z qx qy qz qw frame child`.
"""
import random
import string
import sys

import rclpy.logging
from geometry_msgs.msg import TransformStamped
from node_runtime.spinning import ros_session, spin_until_stopped
from rcl_interfaces.msg import ParameterDescriptor
from rclpy.node import Node
from rclpy.parameter import Parameter
from tf2_py.core_log import ERROR, WARN, log
from tf2_py.maths import quaternion_from_euler
from tf2_ros.static_transform_broadcaster import StaticTransformBroadcaster

USAGE = """\
usage: static_transform_publisher [--x X] [--y Y] [--z Z] [--qx QX] [--qy QY] [--qz QZ] \
[--qw QW] [--roll ROLL] [--pitch PITCH] [--yaw YAW] --frame-id FRAME_ID --child-frame-id \
CHILD_FRAME_ID

A command line utility for manually sending a static transform.

If no translation or orientation is provided, the identity transform will be published.

The translation offsets are in meters.

The rotation may be provided with roll, pitch, yaw euler angles in radians, or as a quaternion.

required arguments:
  --frame-id FRAME_ID parent frame
  --child-frame-id CHILD_FRAME_ID child frame id

optional arguments:
  --x X                 x component of translation
  --y Y                 y component of translation
  --z Z                 z component of translation
  --qx QX               x component of quaternion rotation
  --qy QY               y component of quaternion rotation
  --qz QZ               z component of quaternion rotation
  --qw QW               w component of quaternion rotation
  --roll ROLL           roll component Euler rotation
  --pitch PITCH         pitch component Euler rotation
  --yaw YAW             yaw component Euler rotation"""

TRANSLATION = {'--x': 0, '--y': 1, '--z': 2}
QUATERNION = {'--qx': 0, '--qy': 1, '--qz': 2, '--qw': 3}
EULER = {'--roll': 0, '--pitch': 1, '--yaw': 2}


class ArgumentError(Exception):
    pass


def _float(name: str, text: str) -> float:
    try:
        return float(text)
    except ValueError:
        raise ArgumentError(f'Failed to parse {name} argument as float') from None


def parse(args: list[str]) -> tuple[list[float], list[float], str, str] | None:
    """(translation, quaternion xyzw, frame_id, child_frame_id), or None for --help.
    Raises ArgumentError with upstream's message."""
    if not args:
        raise ArgumentError('Not enough arguments to parse')
    translation, quaternion, euler = [0.0] * 3, [0.0, 0.0, 0.0, 1.0], [0.0] * 3
    frame_id = child_frame_id = ''
    saw = set()
    positional = []
    help_wanted = False
    index = 0
    while index < len(args):
        name = args[index]
        if name in ('--help', '-h'):
            help_wanted = True
        elif name in TRANSLATION or name in QUATERNION or name in EULER or name in (
                '--frame-id', '--child-frame-id'):
            if index == len(args) - 1:
                raise ArgumentError(f'Not enough arguments for {name}')
            index += 1
            value = args[index]
            if name in TRANSLATION:
                translation[TRANSLATION[name]] = _float(name, value)
                saw.add('translation')
            elif name in QUATERNION:
                quaternion[QUATERNION[name]] = _float(name, value)
                saw.add('quaternion')
            elif name in EULER:
                euler[EULER[name]] = _float(name, value)
                saw.add('euler')
            else:
                saw.add('frame')
                if name == '--frame-id':
                    frame_id = value
                else:
                    child_frame_id = value
        else:
            positional.append(name)
        index += 1
    if help_wanted:
        return None
    if 'euler' in saw and 'quaternion' in saw:
        raise ArgumentError('Cannot specify both quaternion and Euler rotations')
    if 'euler' in saw:
        quaternion = list(quaternion_from_euler(*euler))
    if len(positional) in (8, 9):
        log(WARN, 'Old-style arguments are deprecated; see --help for new-style arguments')
        if saw & {'frame', 'translation', 'quaternion'}:
            raise ArgumentError('Cannot specify both new-style (flags) and old-style (arguments)')
        names = ('x', 'y', 'z', 'yaw', 'pitch', 'roll') if len(positional) == 8 else (
            'x', 'y', 'z', 'qx', 'qy', 'qz', 'qw')
        values = [_float(name, text) for name, text in zip(names, positional, strict=False)]
        translation = values[:3]
        if len(positional) == 8:
            yaw, pitch, roll = values[3:]
            quaternion = list(quaternion_from_euler(roll, pitch, yaw))
        else:
            quaternion = values[3:]
        frame_id, child_frame_id = positional[-2:]
    elif positional:
        raise ArgumentError('Extra unparsed arguments on command-line')
    if not frame_id:
        raise ArgumentError('Frame id must not be empty')
    if not child_frame_id:
        raise ArgumentError('Child frame id must not be empty')
    return translation, quaternion, frame_id, child_frame_id



def unique_node_name() -> str:
    alphabet = string.digits + string.ascii_letters
    return 'static_transform_publisher_' + ''.join(random.choices(alphabet, k=16))


class StaticTransformPublisher(Node):
    """Declares the transform as read-only parameters (upstream's names) and publishes it
    once on /tf_static (transient-local: late listeners still get it)."""

    def __init__(self, translation: list[float], quaternion: list[float], frame_id: str,
                 child_frame_id: str) -> None:
        values = dict(zip(('translation.x', 'translation.y', 'translation.z', 'rotation.x',
                           'rotation.y', 'rotation.z', 'rotation.w'),
                          translation + quaternion, strict=True))
        values.update(frame_id=frame_id, child_frame_id=child_frame_id)
        super().__init__(unique_node_name(), parameter_overrides=[
            Parameter(name, value=value) for name, value in values.items()])
        read_only = ParameterDescriptor(read_only=True)
        for name in values:
            self.declare_parameter(name, values[name], read_only)
        transform = TransformStamped()
        transform.header.stamp = self.get_clock().now().to_msg()
        transform.header.frame_id = frame_id
        transform.child_frame_id = child_frame_id
        t, q = transform.transform.translation, transform.transform.rotation
        t.x, t.y, t.z = translation
        q.x, q.y, q.z, q.w = quaternion
        self.broadcaster = StaticTransformBroadcaster(self)
        self.broadcaster.sendTransform(transform)


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv if argv is None else argv
    with ros_session(argv) as stop:
        args = rclpy.utilities.remove_ros_args(argv)[1:]
        try:
            parsed = parse(args)
        except ArgumentError as error:
            log(ERROR, f'error parsing command line arguments: {error}')
            print(USAGE)
            return 1
        if parsed is None:
            print(USAGE)
            return 0
        translation, quaternion, frame_id, child_frame_id = parsed
        if frame_id == child_frame_id:
            name = unique_node_name()
            rclpy.logging.get_logger(name).error(
                f"cannot publish static transform from '{frame_id}' to '{child_frame_id}', "
                'exiting')
            return 1
        node = StaticTransformPublisher(translation, quaternion, frame_id, child_frame_id)
        x, y, z = translation
        qx, qy, qz, qw = quaternion
        node.get_logger().info(
            f"Spinning until stopped - publishing transform\ntranslation: ('{x:f}', '{y:f}', "
            f"'{z:f}')\nrotation: ('{qx:f}', '{qy:f}', '{qz:f}', '{qw:f}')\nfrom "
            f"'{frame_id}' to '{child_frame_id}'")
        spin_until_stopped(node, stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
