"""turtle_teleop_key, draw_square and mimic against a real turtlesim."""

from __future__ import annotations

import os
import signal
import termios
import time

import pytest
from geometry_msgs.msg import Twist
from turtlesim.msg import Pose
from turtlesim.srv import Spawn
from turtlesim_py.teleop import INSTRUCTIONS, Command, decode_key

from ws_testing import Terminal, executable, turtle_qos


@pytest.mark.parametrize('key, command', [
    (b'A', Command('move', linear=1.0)),
    (b'B', Command('move', linear=-1.0)),
    (b'C', Command('move', angular=-1.0)),
    (b'D', Command('move', angular=1.0)),
    (b'g', Command('rotate', theta=0.0)),
    (b't', Command('rotate', theta=0.7854)),
    (b'r', Command('rotate', theta=1.5708)),
    (b'e', Command('rotate', theta=2.3562)),
    (b'd', Command('rotate', theta=3.1416)),
    (b'c', Command('rotate', theta=-2.3562)),
    (b'v', Command('rotate', theta=-1.5708)),
    (b'b', Command('rotate', theta=-0.7854)),
    (b'f', Command('cancel')),
    (b'q', Command('quit')),
    (b'\x1b', None), (b'[', None), (b'G', None), (b'Q', None), (b'x', None), (b'a', None),
])
def test_decode_key(key, command):
    assert decode_key(key[0]) == command


@pytest.fixture
def teleop(ros_env):
    session = Terminal([executable('turtlesim', 'turtle_teleop_key')], ros_env)
    yield session
    session.close()


def wait_raw(teleop: Terminal) -> None:
    deadline = time.monotonic() + 10
    while termios.tcgetattr(teleop.slave)[3] & termios.ICANON:
        assert time.monotonic() < deadline, 'teleop never switched the terminal to raw mode'
        time.sleep(0.05)


def test_teleop_keys_publish_twists_and_q_restores_terminal(teleop, probe):
    twists = probe.collect(Twist, '/turtle1/cmd_vel', turtle_qos())
    teleop.wait_for_output(INSTRUCTIONS)
    wait_raw(teleop)
    raw = termios.tcgetattr(teleop.slave)
    assert not raw[3] & termios.ECHO
    assert raw[6][termios.VMIN] == 0 and raw[6][termios.VTIME] == 1
    probe.spin_until(lambda: probe.node.count_publishers('/turtle1/cmd_vel') > 0, 10,
                     'the teleop publisher')
    probe.spin_for(0.5)
    teleop.press(b'\x1b[A')
    probe.spin_until(lambda: len(twists) == 1, 5, 'the up-arrow twist')
    teleop.press(b'x\x1b[D')
    probe.spin_until(lambda: len(twists) == 2, 5, 'the left-arrow twist')
    teleop.press(b'C')
    probe.spin_until(lambda: len(twists) == 3, 5, 'the right-arrow twist')
    probe.spin_for(0.3)
    assert [(t.linear.x, t.linear.y, t.angular.z) for t in twists] == [
        (2.0, 0.0, 0.0), (0.0, 0.0, 2.0), (0.0, 0.0, -2.0)]
    teleop.press(b'q')
    assert teleop.process.wait(timeout=10) == 0
    assert termios.tcgetattr(teleop.slave) == teleop.before


def test_teleop_ctrl_c_exits_0_and_restores_terminal(teleop):
    teleop.wait_for_output(INSTRUCTIONS)
    wait_raw(teleop)
    os.killpg(teleop.process.pid, signal.SIGINT)
    assert teleop.process.wait(timeout=10) == 0
    assert termios.tcgetattr(teleop.slave) == teleop.before
    assert b'Traceback' not in teleop.output


def test_teleop_rotation_keys_and_cancel(launch, teleop, probe, tmp_path):
    sim = launch('turtlesim', 'turtlesim_node', '--headless', '--canvas-png',
                 str(tmp_path / 'c.png'))
    sim.wait_for_output(r'Spawning turtle \[turtle1\]')
    poses = probe.collect(Pose, '/turtle1/pose', turtle_qos())
    teleop.wait_for_output(INSTRUCTIONS)
    wait_raw(teleop)
    probe.spin_until(lambda: poses, 10, 'poses')
    time.sleep(1.0)  # let teleop's action client discover the server
    teleop.press(b'r')
    sim.wait_for_output(r'Rotation goal completed successfully', timeout=10)
    probe.spin_for(0.2)
    assert abs(poses[-1].theta - 1.5708) < 0.02
    teleop.press(b'd')
    probe.spin_until(lambda: poses[-1].angular_velocity == 1.0, 5, 'the rotation to d')
    teleop.press(b'f')
    sim.wait_for_output(r'\[INFO\] .*Rotation goal canceled', timeout=5)
    teleop.press(b'q')
    assert teleop.process.wait(timeout=10) == 0


def test_draw_square_drives_a_square(launch, tmp_path):
    sim = launch('turtlesim', 'turtlesim_node', '--headless', '--canvas-png',
                 str(tmp_path / 'c.png'))
    sim.wait_for_output(r'Spawning turtle \[turtle1\]')
    square = launch('turtlesim', 'draw_square')
    square.wait_for_output(r'\[INFO\] .*\[draw_square\]: New goal \[7\.544445 5\.544445, '
                           r'0\.000000\]$')
    square.wait_for_output(r'\[draw_square\]: Reached goal$', timeout=15)
    square.wait_for_output(r'New goal \[7\.5\d+ 5\.5\d+, 1\.57\d+\]$', timeout=5)
    assert square.stop() == 0 and 'Traceback' not in square.output, square.output


def test_mimic_copies_velocities(launch, probe, tmp_path):
    sim = launch('turtlesim', 'turtlesim_node', '--headless', '--canvas-png',
                 str(tmp_path / 'c.png'))
    sim.wait_for_output(r'Spawning turtle \[turtle1\]')
    assert probe.call(Spawn, '/spawn', Spawn.Request(x=2.0, y=2.0, name='turtle2')).name
    mimic = launch('turtlesim', 'mimic', '--ros-args', '-r', 'input/pose:=/turtle1/pose',
                   '-r', 'output/cmd_vel:=/turtle2/cmd_vel')
    poses = probe.collect(Pose, '/turtle2/pose', turtle_qos())
    publisher = probe.node.create_publisher(Twist, '/turtle1/cmd_vel', turtle_qos())
    probe.spin_until(lambda: publisher.get_subscription_count() > 0, 10, 'turtle1/cmd_vel')
    probe.spin_until(lambda: probe.node.count_subscribers('/turtle2/cmd_vel') > 1
                     or probe.node.count_publishers('/turtle2/cmd_vel') > 0, 10, 'mimic')
    twist = Twist()
    twist.linear.x = 1.0
    twist.angular.z = 0.5
    publisher.publish(twist)
    probe.spin_until(lambda: poses and poses[-1].angular_velocity == 0.5, 5, 'turtle2 turning')
    assert poses[-1].linear_velocity == 1.0
    # Ctrl-C while mimic is busy copying poses: a clean exit, no traceback.
    assert mimic.stop() == 0 and 'Traceback' not in mimic.output, mimic.output
