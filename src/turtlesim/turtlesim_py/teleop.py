"""turtle_teleop_key: drive turtle1 from the keyboard (raw terminal, restored on every exit)."""

from __future__ import annotations

import os
import sys
import termios
import threading
from dataclasses import dataclass

from geometry_msgs.msg import Twist
from node_runtime.keyboard import RawTerminal
from node_runtime.rclcpp_parity import RclcppParameters, declare_rclcpp_parameters
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.action import ActionClient
from rclpy.node import Node
from turtlesim.action import RotateAbsolute

from turtlesim_py.turtle import TOPIC_QOS

INSTRUCTIONS = (
    'Reading from keyboard\n'
    '---------------------------\n'
    'Use arrow keys to move the turtle.\n'
    "Use G|B|V|C|D|E|R|T keys to rotate to absolute orientations. 'F' to cancel a rotation.\n"
    "'Q' to quit.")

ROTATIONS = {'g': 0.0, 't': 0.7854, 'r': 1.5708, 'e': 2.3562, 'd': 3.1416,
             'c': -2.3562, 'v': -1.5708, 'b': -0.7854}


@dataclass(frozen=True)
class Command:
    """What one input byte asks for. kind: move, rotate, cancel, quit."""

    kind: str
    linear: float = 0.0
    angular: float = 0.0
    theta: float = 0.0


def decode_key(byte: int) -> Command | None:
    """Map one input byte to a command (None: ignored). Arrows arrive as ESC [ A..D."""
    char = chr(byte)
    if char == 'A':
        return Command('move', linear=1.0)
    if char == 'B':
        return Command('move', linear=-1.0)
    if char == 'C':
        return Command('move', angular=-1.0)
    if char == 'D':
        return Command('move', angular=1.0)
    if char in ROTATIONS:
        return Command('rotate', theta=ROTATIONS[char])
    if char == 'f':
        return Command('cancel')
    if char == 'q':
        return Command('quit')
    return None


class TeleopTurtle(RclcppParameters, Node):
    def __init__(self) -> None:
        super().__init__('teleop_turtle')
        self.declare_parameter('scale_linear', 2.0)
        self.declare_parameter('scale_angular', 2.0)
        declare_rclcpp_parameters(self)
        self.twist_pub = self.create_publisher(Twist, 'turtle1/cmd_vel', TOPIC_QOS)
        self.rotate_client = ActionClient(self, RotateAbsolute, 'turtle1/rotate_absolute')
        self.goal_handle = None

    def apply(self, command: Command) -> None:
        if command.kind == 'move':
            twist = Twist()
            twist.linear.x = command.linear * self.get_parameter('scale_linear').value
            twist.angular.z = command.angular * self.get_parameter('scale_angular').value
            self.twist_pub.publish(twist)
        elif command.kind == 'rotate':
            future = self.rotate_client.send_goal_async(RotateAbsolute.Goal(theta=command.theta))
            future.add_done_callback(self._remember_goal)
        elif command.kind == 'cancel' and self.goal_handle is not None:
            try:
                self.goal_handle.cancel_goal_async()
            except Exception:
                pass

    def _remember_goal(self, future) -> None:
        try:
            self.goal_handle = future.result()
        except Exception:
            pass


def key_loop(node: TeleopTurtle, fd: int, stop: threading.Event) -> int:
    print(INSTRUCTIONS, flush=True)
    with RawTerminal(fd):  # a read returns within 0.1 s: Ctrl-C (which sets stop) is seen
        while not stop.is_set():
            try:
                data = os.read(fd, 1)
            except InterruptedError:
                continue
            except OSError as error:
                print(f'read(): {os.strerror(error.errno)}', file=sys.stderr)
                return 255
            if not data:
                continue
            command = decode_key(data[0])
            if command is None:
                continue
            if command.kind == 'quit':
                break
            node.apply(command)
    return 0


def main(argv: list[str] | None = None) -> int:
    with ros_session(sys.argv if argv is None else argv) as stop:
        node = TeleopTurtle()
        # ROS callbacks (the rotation goals' answers) on a thread, the keys on this one.
        spinner = threading.Thread(target=spin_until_stopped, args=(node, stop), daemon=True)
        spinner.start()
        try:
            status = key_loop(node, sys.stdin.fileno(), stop)
        except termios.error as error:
            print(f'turtle_teleop_key needs a terminal on stdin: {error}', file=sys.stderr)
            status = 1
        finally:
            # The spinning thread destroys the node once it has stopped.
            stop.set()
            spinner.join(timeout=5.0)
    return status
