"""turtle_controller against a stand-in turtle whose set_pen answers 500 ms late.

The stand-in (turtle_stand_in.py beside this file) is a real rclpy node: it publishes poses swinging
across x = 5.5 at 62.5 Hz and serves /turtle1/set_pen slowly, logging when each request
arrived and when it was answered.
"""

import re
import sys
import time
from itertools import pairwise
from pathlib import Path

from geometry_msgs.msg import Twist
from turtlesim.msg import Pose

from ws_testing import Background, collect_stamped, wait_until

REQUEST = re.compile(r'set_pen received r=(\d+) g=(\d+) b=(\d+) width=(\d+) off=(\d+) at=([\d.]+)')
ANSWER = re.compile(r'set_pen answered at=([\d.]+)')
RED, GREEN = (255, 0, 0), (0, 255, 0)


def stand_in_argv(*args: str) -> list[str]:
    """Command line of turtle_stand_in.py (a scripted turtle1 with a slow set_pen)."""
    return [sys.executable, str(Path(__file__).with_name('turtle_stand_in.py')), *args]


def _requests(output):
    return [((int(r), int(g), int(b)), int(w), int(off), float(t))
            for r, g, b, w, off, t in REQUEST.findall(output)]


def _side_changes(poses, start, end):
    sides = [msg.x >= 5.5 for t, msg in poses if start <= t <= end]
    return sum(a != b for a, b in pairwise(sides))


def test_cmd_vel_keeps_pose_rate_while_set_pen_is_slow(launch, probe):
    stand_in = launch(argv=stand_in_argv('--path', 'cross', '--period', '2.0',
                                         '--set-pen-delay', '0.5'))
    stand_in.wait_for_output('stand-in ready')
    poses = collect_stamped(probe, Pose, '/turtle1/pose')
    commands = collect_stamped(probe, Twist, '/turtle1/cmd_vel')
    with Background(probe):  # arrival times are stamped as messages arrive
        wait_until(lambda: len(poses) > 10, 10, 'poses from the stand-in')
        controller = launch('my_robot_controller', 'turtle_controller')
        stand_in.wait_for_output(REQUEST.pattern, timeout=15)
        # Discovery may take the probe a few seconds to hear the controller: measure after.
        wait_until(lambda: commands, 20, 'cmd_vel from the controller')
        heard = commands[0][0]
        time.sleep(6.5)
        stopping = time.time()
        controller.stop()
        time.sleep(0.6)  # let the last slow answer arrive
    requests = _requests(stand_in.output)
    answers = [float(t) for t in ANSWER.findall(stand_in.output)]
    assert len(requests) >= 5, stand_in.output
    # One call per side change, colours alternating, never a repeat for the same side.
    colours = [colour for colour, *_ in requests]
    assert all(a != b for a, b in pairwise(colours)), colours
    assert set(colours) == {RED, GREEN}
    assert all(width == 3 and off == 0 for _, width, off, _ in requests)
    # Side changes the controller saw: from its first request (made for the side it then
    # saw) until it was stopped.
    crossings = _side_changes(poses, requests[0][3], stopping)
    assert abs(len(requests) - (1 + crossings)) <= 1, (len(requests), crossings)

    # While each request waits its 500 ms, cmd_vel keeps coming, one per pose.
    rates = []
    for (_, _, _, received), answered in zip(requests, answers, strict=False):
        if received < heard or answered > stopping:
            continue
        window = answered - received
        assert window >= 0.45
        in_window = [t for t, _ in commands if received <= t <= answered]
        poses_in_window = [t for t, _ in poses if received <= t <= answered]
        rates.append(len(in_window) / window)
        assert len(in_window) >= 0.9 * len(poses_in_window), (len(in_window), poses_in_window)
    assert len(rates) >= 4
    start = max(requests[0][3], heard)
    pose_rate = len([t for t, _ in poses if start <= t <= stopping]) / (stopping - start)
    print(f'pose rate {pose_rate:.1f} Hz; cmd_vel rate during slow set_pen calls: '
          f'min {min(rates):.1f} Hz, mean {sum(rates) / len(rates):.1f} Hz; '
          f'{len(requests)} calls, {crossings} side changes')
    assert min(rates) >= 0.85 * pose_rate
    assert 'pen colour applied: green (0, 255, 0)' in controller.output
    assert 'pen colour applied: red (255, 0, 0)' in controller.output


def test_no_set_pen_calls_while_staying_on_one_side(launch, probe):
    stand_in = launch(argv=stand_in_argv('--path', 'hold', '--hold-x', '3.0'))
    commands = collect_stamped(probe, Twist, '/turtle1/cmd_vel')
    controller = launch('my_robot_controller', 'turtle_controller')
    controller.wait_for_output(r'pen colour applied: red \(255, 0, 0\)', timeout=15)
    with Background(probe):
        wait_until(lambda: commands, 20, 'cmd_vel from the controller')
        since = time.time()
        time.sleep(3.0)
    controller.stop()
    requests = _requests(stand_in.output)
    assert [colour for colour, *_ in requests] == [RED], stand_in.output
    # It kept driving all along (~62.5 Hz), with a single call at the start.
    assert len([t for t, _ in commands if t >= since]) >= 150
    assert controller.output.count('pen colour applied') == 1
