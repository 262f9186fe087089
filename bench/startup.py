"""Start-up: `ros2 run turtlesim turtlesim_node` to its first pose, and `turtle_controller` to
its first set_pen applied by turtlesim, next to a minimal rclpy node doing the same, each with a
warm page cache and (as root) a cold one (`/proc/sys/vm/drop_caches`).

`python bench/startup.py [--runs N]` alone, or `scripts/bench --only startup`.
A probe node (started first, so discovery is not what is measured twice) receives the pose, and
turtlesim's service introspection reports the set_pen response it sent.
"""

from __future__ import annotations

import argparse
import os
import signal
import sys
import time
from collections.abc import Callable
from pathlib import Path

from common import Row, Session, executable, percentile, session

RUNS = 5
BOUND = 30.0  # seconds: a start slower than this is a failure, not a figure
RESPONSE_SENT = 2  # service_msgs/msg/ServiceEventInfo

# The baselines: the least an rclpy node must do for the same observable event.
MINIMAL_PUBLISHER = '''
import rclpy
from rclpy.node import Node
from turtlesim.msg import Pose
rclpy.init()
node = Node('minimal_publisher')
publisher = node.create_publisher(Pose, '/turtle1/pose', 10)
node.create_timer(0.016, lambda: publisher.publish(Pose()))
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
'''
MINIMAL_CLIENT = '''
import rclpy
from rclpy.node import Node
from turtlesim.srv import SetPen
rclpy.init()
node = Node('minimal_client')
client = node.create_client(SetPen, '/turtle1/set_pen')
client.wait_for_service()
future = client.call_async(SetPen.Request(r=0, g=255, b=0, width=3, off=0))
try:
    rclpy.spin_until_future_complete(node, future)
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
'''


def drop_page_cache() -> bool:
    """Evict file pages (the wheels' shared libraries, Python modules); False if not root."""
    try:
        os.sync()
        Path('/proc/sys/vm/drop_caches').write_text('3\n')
        return True
    except OSError:
        return False


def drain(probe, seen: list) -> None:
    """Take what the previous run's process still had in flight, then forget it."""
    deadline = time.monotonic() + 0.5
    while time.monotonic() < deadline:
        probe.executor.spin_once(timeout_sec=0.05)
    seen.clear()


def time_to(session: Session, argv: list[str], happened: Callable[[], bool], spin: Callable,
            cold: bool) -> float:
    """Seconds from starting `argv` to `happened()`; the process is stopped afterwards."""
    if cold and not drop_page_cache():
        raise PermissionError('a cold start needs root (writing /proc/sys/vm/drop_caches)')
    started = time.monotonic()
    process = session.start_argv(argv)
    try:
        spin(happened, BOUND, f'{argv[-1]!r} to be seen')
        return time.monotonic() - started
    finally:
        os.killpg(process.popen.pid, signal.SIGINT)
        process.wait(timeout=15)


def run(session: Session, runs: int = RUNS) -> tuple[list[Row], dict]:
    from turtlesim.msg import Pose
    from turtlesim.srv import SetPen

    probe = session.probe()
    poses: list[Pose] = []
    responses: list[float] = []
    probe.node.create_subscription(Pose, '/turtle1/pose', poses.append, 10)
    probe.node.create_subscription(
        SetPen.Event, '/turtle1/set_pen/_service_event',
        lambda event: responses.append(time.monotonic())
        if event.info.event_type == RESPONSE_SENT else None, 10)
    modes = ['warm'] + (['cold'] if os.geteuid() == 0 else [])
    cases = {
        'turtlesim_node to first pose': (['ros2', 'run', 'turtlesim', 'turtlesim_node',
                                          '--headless'], poses),
        # the same without `ros2 run` (which finds the executable, then execs it)
        'turtlesim_node executable to first pose': ([executable('turtlesim', 'turtlesim_node'),
                                                     '--headless'], poses),
        'minimal rclpy publisher to first message': ([sys.executable, '-c', MINIMAL_PUBLISHER],
                                                     poses),
    }
    data: dict[str, list[float]] = {}
    try:
        for mode in modes:
            for name, (argv, seen) in cases.items():
                samples = data.setdefault(f'{name} ({mode})', [])
                for _ in range(runs):
                    drain(probe, seen)
                    samples.append(time_to(session, argv, lambda seen=seen: bool(seen),
                                           probe.spin_until, mode == 'cold'))
        # The controller and its baseline need a running turtlesim that reports its responses.
        session.start('turtlesim', 'turtlesim_node', '--headless',
                      '--service-introspection', 'metadata')
        probe.spin_until(lambda: bool(poses), BOUND, 'turtlesim for the set_pen cases')
        clients = {
            'turtle_controller to first set_pen applied': ['ros2', 'run', 'my_robot_controller',
                                                           'turtle_controller'],
            'minimal rclpy client to first set_pen applied': [sys.executable, '-c',
                                                              MINIMAL_CLIENT],
        }
        for mode in modes:
            for name, argv in clients.items():
                samples = data.setdefault(f'{name} ({mode})', [])
                for _ in range(runs):
                    drain(probe, responses)
                    samples.append(time_to(session, argv, lambda: bool(responses),
                                           probe.spin_until, mode == 'cold'))
    finally:
        probe.close()
    rows = [Row('startup', f'{name}, p50 / max of {len(samples)}',
                f'{percentile(samples, 50):.2f} / {max(samples):.2f} s')
            for name, samples in data.items()]
    return rows, {'startup': data}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--runs', type=int, default=RUNS)
    options = parser.parse_args()
    with session('startup') as current:
        rows, _ = run(current, options.runs)
    for row in rows:
        print(f'{row.metric}: {row.value}')


if __name__ == '__main__':
    main()
