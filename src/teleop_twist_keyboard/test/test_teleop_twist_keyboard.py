"""teleop_twist_keyboard typed at on a terminal, as every simulation page has the learner run
it: its help, its keys and speed keys on /cmd_vel, its parameters, and turtlesim driven by it
remapped to /turtle1/cmd_vel."""

from __future__ import annotations

import subprocess
import termios

import pytest
from geometry_msgs.msg import Twist, TwistStamped
from turtlesim.msg import Pose

from ws_testing import Terminal, executable, turtle_qos

TELEOP = executable('teleop_twist_keyboard', 'teleop_twist_keyboard')
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


@pytest.fixture
def terminals():
    opened: list[Terminal] = []

    def open_terminal(*args: str, env: dict[str, str]) -> Terminal:
        opened.append(Terminal([TELEOP, *args], env))
        return opened[-1]

    yield open_terminal
    for terminal in opened:
        terminal.close()


def velocities(twist: Twist) -> tuple[float, ...]:
    return (round(twist.linear.x, 6), round(twist.linear.y, 6), round(twist.linear.z, 6),
            round(twist.angular.z, 6))


def test_keys_publish_twists_on_cmd_vel(terminals, ros_env, probe) -> None:
    twists = probe.collect(Twist, '/cmd_vel')
    stamped = probe.collect(TwistStamped, '/stamped_cmd_vel')
    teleop = terminals(env=ros_env)
    # Started alongside: `stamped` publishes TwistStamped in `frame_id`.
    stamped_teleop = terminals('--ros-args', '-p', 'stamped:=true', '-p', 'frame_id:=base_link',
                               '-r', 'cmd_vel:=stamped_cmd_vel', env=ros_env)
    teleop.wait_for_output(HELP + '\ncurrently:\tspeed 0.5\tturn 1.0 \n')
    probe.spin_until(lambda: probe.node.count_publishers('/cmd_vel') == 1, 10, 'the publisher')
    probe.spin_for(0.5)  # the teleop's side of the match too (a volatile topic)
    assert not termios.tcgetattr(teleop.slave)[3] & termios.ECHO  # keys are not echoed
    expected = []
    for key, twist in ((b'i', (0.5, 0, 0, 0)), (b'u', (0.5, 0, 0, 1.0)),
                       (b'q', (0.55, 0, 0, 1.1)),  # the speeds grow, the direction stays
                       (b'J', (0, 0.55, 0, 0)), (b'.', (-0.55, 0, 0, 1.1)),
                       (b'x', (-0.495, 0, 0, 1.1)), (b't', (0, 0, 0.495, 0)),
                       (b'k', (0, 0, 0, 0)), (b'>', (-0.495, -0.495, 0, 0)),
                       (b'e', (-0.495, -0.495, 0, 0)),
                       (b'!', (0, 0, 0, 0))):  # anything else: stop
        teleop.press(key)
        expected.append(twist)
        probe.spin_until(lambda: len(twists) == len(expected), 5, f'the twist of {key}')
    assert [velocities(twist) for twist in twists] == [
        tuple(round(value, 6) for value in twist) for twist in expected]
    teleop.wait_for_output('currently:\tspeed 0.55\tturn 1.1 \n'
                           'currently:\tspeed 0.49500000000000005\tturn 1.1 \n'
                           'currently:\tspeed 0.49500000000000005\tturn 1.2100000000000002 \n')
    teleop.press(b'i\x03')  # Ctrl-C in a raw terminal: the robot is stopped on the way out
    assert teleop.process.wait(timeout=10) == 0
    probe.spin_until(lambda: len(twists) == len(expected) + 2, 5, 'the last stop')
    assert velocities(twists[-1]) == (0, 0, 0, 0)
    assert termios.tcgetattr(teleop.slave) == teleop.before
    assert 'Traceback' not in teleop.text

    stamped_teleop.wait_for_output('currently:')
    probe.spin_until(lambda: probe.node.count_publishers('/stamped_cmd_vel') == 1, 10,
                     'the stamped publisher')
    probe.spin_for(0.5)  # the teleop's side of the match too
    stamped_teleop.press(b'l')
    probe.spin_until(lambda: stamped, 5, 'a TwistStamped')
    assert stamped[0].header.frame_id == 'base_link'
    assert stamped[0].header.stamp.sec > 0
    assert velocities(stamped[0].twist) == (0, 0, 0, -1.0)


def test_drives_turtlesim_with_repeat_rate_and_key_timeout(terminals, launch, ros_env,
                                                           probe) -> None:
    launch('turtlesim', 'turtlesim_node', '--headless').wait_for_output(
        r'Spawning turtle \[turtle1\]')
    poses: list[Pose] = []
    probe.node.create_subscription(Pose, '/turtle1/pose', poses.append, turtle_qos())
    twists = probe.collect(Twist, '/turtle1/cmd_vel', turtle_qos())
    teleop = terminals('--ros-args', '-r', 'cmd_vel:=/turtle1/cmd_vel',
                       '-p', 'repeat_rate:=20.0', '-p', 'key_timeout:=0.6', '-p', 'speed:=2',
                       env=ros_env)
    teleop.wait_for_output('currently:\tspeed 2.0\tturn 1.0 ')
    probe.spin_until(lambda: probe.node.count_subscribers('/turtle1/cmd_vel') == 2 and poses
                     and probe.node.count_publishers('/turtle1/cmd_vel') == 1,
                     10, 'the turtle and the teleop')
    # The teleop's side of the matches too: twists sent before it were lost (CI-like load saw
    # 3 of the ~12).
    probe.spin_for(0.5)
    start = poses[-1]
    teleop.press(b'i')  # one key press: repeated at 20 Hz until the key timeout stops it

    def stopped_after_moving() -> bool:
        moved = [i for i, twist in enumerate(twists) if velocities(twist) == (2.0, 0, 0, 0)]
        return bool(moved) and any(velocities(twist) == (0, 0, 0, 0)
                                   for twist in twists[moved[-1]:])

    probe.spin_until(stopped_after_moving, 5, 'the stop after the key timeout')
    moving = [t for t in twists if velocities(t) == (2.0, 0, 0, 0)]
    assert 5 <= len(moving) <= 16, len(moving)  # ~0.6 s at 20 Hz; before and after: stops
    probe.spin_until(lambda: poses[-1].linear_velocity == 0.0, 5, 'the turtle stopping')
    end = poses[-1]
    # Straight ahead (turtle1 starts facing +x), about 2 m/s for the ~0.6 s the key held.
    assert end.y == pytest.approx(start.y, abs=1e-3)
    assert 0.8 < end.x - start.x < 2.0, (start, end)
    teleop.press(b'\x03')
    assert teleop.process.wait(timeout=10) == 0


BAD_PARAMETERS = {
    'speed:=fast': "teleop_twist_keyboard: parameter 'speed' must be a finite number, got 'fast'",
    'repeat_rate:=-1.0': "teleop_twist_keyboard: parameter 'repeat_rate' must be a finite "
                         'number >= 0, got -1.0',
    'frame_id:=base_link': "teleop_twist_keyboard: parameter 'frame_id' can only be set when "
                           "'stamped' is true",
}


def test_bad_input_gets_one_line(terminals, ros_env) -> None:
    # All at once: each is a process start (~1-3 s here) and nothing they share.
    no_terminal = subprocess.Popen([TELEOP], stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                   stderr=subprocess.PIPE, text=True, env=ros_env)
    started = {line: terminals('--ros-args', '-p', parameter, env=ros_env)
               for parameter, line in BAD_PARAMETERS.items()}
    for line, teleop in started.items():
        assert teleop.process.wait(timeout=20) == 1
        teleop.wait_for_output(line)
        assert teleop.text.strip() == line
    out, err = no_terminal.communicate(timeout=20)
    assert (no_terminal.returncode, out) == (1, '')
    assert err == ('teleop_twist_keyboard: stdin is not a terminal: it reads single key '
                   'presses, so run it in a terminal of its own (not from a launch file or a '
                   'pipe)\n')
