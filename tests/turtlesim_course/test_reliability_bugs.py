"""The reliability bugs found by hand, each as the user met it (issue: reliability).

A 300-character spawn name killed turtlesim; NaN cmd_vel logged an error 62 times a second;
every exit wrote turtlesim_canvas.png into the working directory; add_two_ints_client
SIGTERMed while waiting for its server printed an RCLError traceback and exited 1.
"""

from __future__ import annotations

import math
import re
import signal
import time

from geometry_msgs.msg import Twist
from node_runtime.repeat_log import RepeatedLog
from std_srvs.srv import Trigger
from turtlesim.srv import Spawn

from support import RosProcess, executable, turtle_qos


def test_300_character_spawn_name_is_refused_and_turtlesim_lives(launch, probe):
    sim = launch('turtlesim', 'turtlesim_node', '--headless')
    sim.wait_for_output(r'Spawning turtle \[turtle1\]', timeout=20)
    reply = probe.call(Spawn, '/spawn', Spawn.Request(x=1.0, y=1.0, name='a' * 300))
    assert reply.name == ''
    sim.wait_for_output(r"\[ERROR\] .*Refusing to spawn: name='a{60}\.\.\.\(300 characters\)' is "
                        r'not a valid ROS name \(allowed: at most 210 characters here, got 300')
    # The longest name that fits still works, and the node is still serving.
    reply = probe.call(Spawn, '/spawn', Spawn.Request(x=1.0, y=1.0, name='b' * 210))
    assert reply.name == 'b' * 210
    assert sim.popen.poll() is None
    assert sim.stop() == 0 and 'Traceback' not in sim.output, sim.output


def test_nan_cmd_vel_is_logged_once_then_once_a_second_with_a_count(launch, probe):
    sim = launch('turtlesim', 'turtlesim_node', '--headless')
    sim.wait_for_output(r'Spawning turtle \[turtle1\]', timeout=20)
    publisher = probe.node.create_publisher(Twist, '/turtle1/cmd_vel', turtle_qos())
    probe.spin_until(lambda: publisher.get_subscription_count() > 0, 10, 'cmd_vel matched')
    nan = Twist()
    nan.linear.x = math.nan
    start = time.monotonic()
    sent = 0
    while time.monotonic() - start < 2.5:  # 62.5 messages a second, as a controller would
        publisher.publish(nan)
        sent += 1
        probe.spin_for(0.016)
    probe.spin_for(0.3)
    lines = re.findall(r'^\[ERROR\] .*Ignoring turtle1/cmd_vel: linear\.x=nan is not allowed.*$',
                       sim.output, re.MULTILINE)
    assert 2 <= len(lines) <= 4, (sent, lines)
    counts = [int(n) for n in re.findall(r'\((\d+) repeats suppressed since the last report\)',
                                         '\n'.join(lines))]
    assert len(counts) == len(lines) - 1 and sum(counts) >= sent // 2, (sent, lines)


def test_repeated_log_keys_are_independent_and_counted():
    lines: list[str] = []

    class Logger:
        def error(self, text: str) -> None:
            lines.append(text)

    now = [0.0]
    log = RepeatedLog(Logger(), period=1.0, clock=lambda: now[0])
    for _ in range(5):
        log.error(('t1', 'x'), 'x bad')
        log.error(('t1', 'y'), 'y bad')
        now[0] += 0.3
    assert lines == ['x bad', 'y bad', 'x bad (3 repeats suppressed since the last report)',
                     'y bad (3 repeats suppressed since the last report)']


def test_no_canvas_png_unless_asked(ros_env, tmp_path, probe):
    work = tmp_path / 'cwd'
    work.mkdir()

    def turtlesim_in(directory, log: str) -> RosProcess:
        process = RosProcess(['sh', '-c', f'cd "{directory}" && exec "$0" --headless',
                              executable('turtlesim', 'turtlesim_node')], ros_env, tmp_path / log)
        process.wait_for_output(r'Spawning turtle \[turtle1\]', timeout=20)
        return process

    sim = turtlesim_in(work, 'first.log')
    assert sim.stop() == 0, sim.output
    # The probe must have seen the first turtlesim leave: a request sent to its lingering graph
    # entry, before the second one's service matched, was lost (CI's 10 s time-out).
    probe.spin_until(lambda: '/turtlesim/_save_canvas' not in dict(
        probe.node.get_service_names_and_types()), 10, 'the first turtlesim to leave the graph')
    assert list(work.iterdir()) == [], 'a file appeared unasked'
    assert 'Canvas written' not in sim.output
    # Asked through the hidden service: written into the working directory.
    sim = turtlesim_in(work, 'second.log')
    try:
        reply = probe.call(Trigger, '/turtlesim/_save_canvas', Trigger.Request())
        assert reply.success and reply.message == str(work / 'turtlesim_canvas.png')
        assert (work / 'turtlesim_canvas.png').stat().st_size > 0
    finally:
        assert sim.stop() == 0, sim.output


def test_add_two_ints_client_sigterm_while_waiting(launch):
    client = launch('my_robot_controller', 'add_two_ints_client')
    client.wait_for_output(r'service /add_two_ints not available, waiting again\.\.\.', 20)
    client.popen.send_signal(signal.SIGTERM)
    assert client.wait(timeout=10) == 130
    assert 'Traceback' not in client.output and 'RCLError' not in client.output, client.output
