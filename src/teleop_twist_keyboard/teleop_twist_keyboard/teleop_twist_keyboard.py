"""teleop_twist_keyboard: key presses to geometry_msgs/Twist (or TwistStamped) on cmd_vel.

Each movement key sets a direction that is scaled by the current speed (linear) and turn
(angular) and published at once; any other key stops. With `repeat_rate` > 0 the last command
is published again at that rate, and with `key_timeout` > 0 the robot stops when no key came
for that long (so a robot does not drive on after the hand leaves the keyboard).
"""

from __future__ import annotations

import math
import os
import sys
import threading
import time

from geometry_msgs.msg import Twist, TwistStamped
from node_runtime.keyboard import RawTerminal
from node_runtime.spinning import ros_session, spin_until_stopped
from rcl_interfaces.msg import ParameterDescriptor
from rclpy.node import Node

HELP = """
This node takes keypresses from the keyboard and publishes them
as Twist/TwistStamped messages. It works best with a US keyboard layout.
---------------------------
Moving around:
   u    i    o
   j    k    l
   m    ,    .

For Holonomic mode (strafing), hold down the shift key:
---------------------------
   U    I    O
   J    K    L
   M    <    >

t : up (+z)
b : down (-z)

anything else : stop

q/z : increase/decrease max speeds by 10%
w/x : increase/decrease only linear speed by 10%
e/c : increase/decrease only angular speed by 10%

CTRL-C to quit
"""

# key: (x, y, z, yaw) directions, scaled by speed (x, y, z) and turn (yaw).
MOVES = {
    'i': (1, 0, 0, 0), 'o': (1, 0, 0, -1), 'u': (1, 0, 0, 1),
    'j': (0, 0, 0, 1), 'l': (0, 0, 0, -1),
    ',': (-1, 0, 0, 0), '.': (-1, 0, 0, 1), 'm': (-1, 0, 0, -1),
    'I': (1, 0, 0, 0), 'O': (1, -1, 0, 0), 'U': (1, 1, 0, 0),
    'J': (0, 1, 0, 0), 'L': (0, -1, 0, 0),
    '<': (-1, 0, 0, 0), '>': (-1, -1, 0, 0), 'M': (-1, 1, 0, 0),
    't': (0, 0, 1, 0), 'b': (0, 0, -1, 0),
}
# key: (speed factor, turn factor)
SPEED_KEYS = {
    'q': (1.1, 1.1), 'z': (0.9, 0.9),
    'w': (1.1, 1.0), 'x': (0.9, 1.0),
    'e': (1.0, 1.1), 'c': (1.0, 0.9),
}
CTRL_C = '\x03'
STATUS_LINES_PER_HELP = 15  # the help comes back after this many status lines
DYNAMIC = ParameterDescriptor(dynamic_typing=True)  # `-p speed:=1` (an integer) is fine too


def status(speed: float, turn: float) -> str:
    return f'currently:\tspeed {speed}\tturn {turn} '


class TeleopTwistKeyboard(Node):
    def __init__(self) -> None:
        super().__init__('teleop_twist_keyboard')
        self.speed = self._number('speed', 0.5)
        self.turn = self._number('turn', 1.0)
        self.repeat_rate = self._number('repeat_rate', 0.0, minimum=0.0)
        self.key_timeout = self._number('key_timeout', 0.0, minimum=0.0)
        self.stamped = self.declare_parameter('stamped', False, DYNAMIC).value
        self.frame_id = self.declare_parameter('frame_id', '', DYNAMIC).value
        if not isinstance(self.stamped, bool):
            raise ValueError(f"parameter 'stamped' must be true or false, got {self.stamped!r}")
        if not isinstance(self.frame_id, str):
            raise ValueError(f"parameter 'frame_id' must be a string, got {self.frame_id!r}")
        if self.frame_id and not self.stamped:
            raise ValueError("parameter 'frame_id' can only be set when 'stamped' is true")
        self.direction = (0, 0, 0, 0)
        self.lock = threading.Lock()  # the key loop and the repeat timer both publish
        self.publisher = self.create_publisher(
            TwistStamped if self.stamped else Twist, 'cmd_vel', 10)
        if self.repeat_rate > 0.0:
            self.create_timer(1.0 / self.repeat_rate, self.publish)

    def _number(self, name: str, default: float, minimum: float | None = None) -> float:
        value = self.declare_parameter(name, default, DYNAMIC).value
        if isinstance(value, bool) or not isinstance(value, int | float) or \
                not math.isfinite(value) or (minimum is not None and value < minimum):
            allowed = 'a finite number' + ('' if minimum is None else f' >= {minimum:g}')
            raise ValueError(f"parameter '{name}' must be {allowed}, got {value!r}")
        return float(value)

    def publish(self) -> None:
        with self.lock:
            x, y, z, yaw = self.direction
            twist = Twist()
            twist.linear.x = x * self.speed
            twist.linear.y = y * self.speed
            twist.linear.z = z * self.speed
            twist.angular.z = yaw * self.turn
            if self.stamped:
                message = TwistStamped(twist=twist)
                message.header.stamp = self.get_clock().now().to_msg()
                message.header.frame_id = self.frame_id
                self.publisher.publish(message)
            else:
                self.publisher.publish(twist)

    def press(self, key: str) -> str | None:
        """Apply one key; returns the status line a speed key prints."""
        with self.lock:
            line = None
            if key in MOVES:
                self.direction = MOVES[key]
            elif key in SPEED_KEYS:
                speed_factor, turn_factor = SPEED_KEYS[key]
                self.speed *= speed_factor
                self.turn *= turn_factor
                line = status(self.speed, self.turn)
            else:
                self.direction = (0, 0, 0, 0)
        self.publish()
        return line

    def stop(self) -> None:
        with self.lock:
            self.direction = (0, 0, 0, 0)
        self.publish()


def key_loop(node: TeleopTwistKeyboard, fd: int, stop: threading.Event) -> None:
    print(HELP)
    print(status(node.speed, node.turn), flush=True)
    shown = 0
    last_key = time.monotonic()
    with RawTerminal(fd, signals=False):  # Ctrl-C is read as a key, like upstream's
        while not stop.is_set():
            try:
                data = os.read(fd, 1)
            except InterruptedError:
                continue
            if not data:  # no key within 0.1 s
                if node.key_timeout > 0.0 and node.direction != (0, 0, 0, 0) and \
                        time.monotonic() - last_key > node.key_timeout:
                    node.stop()
                continue
            last_key = time.monotonic()
            key = data.decode('latin-1')
            if key == CTRL_C:
                break
            line = node.press(key)
            if line is not None:
                print(line, flush=True)
                shown += 1
                if shown % STATUS_LINES_PER_HELP == 0:
                    print(HELP, flush=True)


def main(argv: list[str] | None = None) -> int:
    fd = sys.stdin.fileno()
    if not os.isatty(fd):
        print('teleop_twist_keyboard: stdin is not a terminal: it reads single key presses, '
              'so run it in a terminal of its own (not from a launch file or a pipe)',
              file=sys.stderr)
        return 1
    with ros_session(sys.argv if argv is None else argv) as stop:
        try:
            node = TeleopTwistKeyboard()
        except ValueError as error:
            print(f'teleop_twist_keyboard: {error}', file=sys.stderr)
            return 1
        spinner = threading.Thread(target=spin_until_stopped, args=(node, stop), daemon=True)
        spinner.start()
        try:
            key_loop(node, fd, stop)
            node.stop()  # the robot must not drive on after the teleop has gone
        finally:
            stop.set()
            spinner.join(timeout=5.0)
    return 0


if __name__ == '__main__':
    sys.exit(main())
