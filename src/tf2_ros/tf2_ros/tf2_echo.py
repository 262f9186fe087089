"""ros2 run tf2_ros tf2_echo SOURCE TARGET [RATE]: print a transform, as upstream prints it."""
import math
import sys
import threading
import time

import rclpy
import rclpy.utilities
from geometry_msgs.msg import TransformStamped
from node_runtime.spinning import SIGNAL_CHECK_PERIOD, ros_session
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.time import Time
from tf2_py import TransformException
from tf2_py.maths import euler_from_quaternion
from tf2_ros.buffer import Buffer
from tf2_ros.transform_listener import TransformListener

USAGE = """\
Usage: tf2_echo source_frame target_frame [echo_rate]

This will echo the transform from the coordinate frame of the source_frame
to the coordinate frame of the target_frame. 
Note: This is the transform to get data from target_frame into the source_frame.
Default echo rate is 1 if echo_rate is not given.
"""  # noqa: W291 (upstream's line ends in a space)


def rotation_matrix(x: float, y: float, z: float, w: float) -> list[list[float]]:
    """The 3x3 rotation matrix of a unit quaternion (tf2's Matrix3x3::setRotation)."""
    s = 2.0 / (x * x + y * y + z * z + w * w)
    xs, ys, zs = x * s, y * s, z * s
    wx, wy, wz = w * xs, w * ys, w * zs
    xx, xy, xz = x * xs, x * ys, x * zs
    yy, yz, zz = y * ys, y * zs, z * zs
    return [[1.0 - (yy + zz), xy - wz, xz + wy],
            [xy + wz, 1.0 - (xx + zz), yz - wx],
            [xz - wy, yz + wx, 1.0 - (xx + yy)]]


def format_transform(transform: TransformStamped) -> str:
    """tf2_echo's block: time, translation, rotation three ways, homogeneous matrix."""
    t, q = transform.transform.translation, transform.transform.rotation
    roll, pitch, yaw = euler_from_quaternion((q.x, q.y, q.z, q.w))
    degrees = 180.0 / math.pi
    lines = [f'At time {transform.header.stamp.sec}.{transform.header.stamp.nanosec}',
             f'- Translation: [{t.x:.3f}, {t.y:.3f}, {t.z:.3f}]',
             f'- Rotation: in Quaternion [{q.x:.3f}, {q.y:.3f}, {q.z:.3f}, {q.w:.3f}]',
             f'- Rotation: in RPY (radian) [{roll:.3f}, {pitch:.3f}, {yaw:.3f}]',
             f'- Rotation: in RPY (degree) [{roll * degrees:.3f}, {pitch * degrees:.3f}, '
             f'{yaw * degrees:.3f}]',
             '- Matrix:']
    for row, offset in zip(rotation_matrix(q.x, q.y, q.z, q.w), (t.x, t.y, t.z), strict=True):
        lines.append(''.join(f' {value:6.3f}' for value in (*row, offset)))
    lines.append(''.join(f' {value:6.3f}' for value in (0.0, 0.0, 0.0, 1.0)))
    return '\n'.join(lines) + '\n'


class Tf2Echo(Node):
    def __init__(self) -> None:
        super().__init__('tf2_echo')
        self.buffer = Buffer()
        self.listener = TransformListener(self.buffer, self)


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv if argv is None else argv
    args = rclpy.utilities.remove_ros_args(argv)
    if len(args) not in (3, 4):
        print(USAGE, end='')
        return 1
    rate = 1.0
    if len(args) == 4:
        try:
            rate = float(args[3])
        except ValueError:
            print(f"Failed to convert rate argument '{args[3]}' to a floating-point number",
                  file=sys.stderr)
            return 2
        if not math.isfinite(rate) or rate <= 0.0:
            print(f"Rate argument '{args[3]}' must be a positive number", file=sys.stderr)
            return 2
    source, target = args[1], args[2]
    with ros_session(argv) as stop:
        node = Tf2Echo()
        executor = SingleThreadedExecutor()
        executor.add_node(node)
        try:
            _echo(node, executor, source, target, 1.0 / rate, stop)
        finally:
            executor.shutdown(timeout_sec=1.0)
            node.destroy_node()
    return 0


def _echo(node: Tf2Echo, executor: SingleThreadedExecutor, source: str, target: str,
          period: float, stop: threading.Event) -> None:
    """Spin between prints, so /tf keeps arriving; first wait until the transform exists."""
    logger = node.get_logger()
    found = False
    due = time.monotonic()
    while not stop.is_set() and rclpy.ok():
        executor.spin_once(timeout_sec=min(SIGNAL_CHECK_PERIOD, max(0.0, due - time.monotonic())))
        if time.monotonic() < due:
            continue
        due += period
        if not found:
            found, why = node.buffer.can_transform_core(source, target, Time())
            if not found:
                logger.info(f'Waiting for transform {source} ->  {target}: {why}',
                            throttle_duration_sec=1.0)
                continue
        try:
            print(format_transform(node.buffer.lookup_transform(source, target, Time())),
                  end='', flush=True)
        except TransformException as error:
            print(f'Failure at {node.get_clock().now().nanoseconds / 1e9:.3f}\n'
                  f'Exception thrown:{error}\nThe current list of frames is:\n'
                  f'{node.buffer.all_frames_as_string()}', flush=True)

if __name__ == '__main__':
    sys.exit(main())
