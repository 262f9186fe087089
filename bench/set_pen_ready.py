"""Why set_pen looks "not ready" for seconds under 200 turtles: what a newcomer sees, when.

turtlesim with N turtles (default 200, ~20 DDS endpoints each); then, several times, a fresh
participant (as turtle_controller is) subscribes to /turtle1/pose and makes a SetPen client,
and records every 20 ms: a pose received, the server's request reader and reply writer in its
graph cache (rq/turtle1/set_penRequest, rr/turtle1/set_penReply), service_is_ready(), and
whether a set_pen call sent at once is answered.
"""

from __future__ import annotations

import argparse
import sys
import time

from turtlesim.msg import Pose
from turtlesim.srv import SetPen

from common import TestNode, session
from scale import _spawn_all as spawn_all

REQUEST_TOPIC = 'rq/turtle1/set_penRequest'
REPLY_TOPIC = 'rr/turtle1/set_penReply'


def newcomer(domain: int, bound: float) -> dict[str, float | None]:
    """Seconds from the newcomer's creation to each event (None: not within `bound`)."""
    start = time.monotonic()
    probe = TestNode(domain, 'newcomer')
    seen: dict[str, float | None] = dict.fromkeys(
        ('pose', 'request reader', 'reply writer', 'service_is_ready', 'first call answered'))
    poses: list[Pose] = []
    probe.node.create_subscription(Pose, '/turtle1/pose', poses.append, 7)
    client = probe.node.create_client(SetPen, '/turtle1/set_pen')
    future = None
    try:
        while time.monotonic() - start < bound and None in seen.values():
            probe.executor.spin_once(timeout_sec=0.02)
            now = time.monotonic() - start
            checks = {
                'pose': bool(poses),
                'request reader': bool(probe.node.get_subscriptions_info_by_topic(
                    REQUEST_TOPIC, no_mangle=True)),
                'reply writer': bool(probe.node.get_publishers_info_by_topic(
                    REPLY_TOPIC, no_mangle=True)),
                'service_is_ready': client.service_is_ready(),
                'first call answered': future is not None and future.done(),
            }
            for key, ok in checks.items():
                if ok and seen[key] is None:
                    seen[key] = now
            if future is None and seen['request reader'] is not None:
                # Sent as soon as the server's request reader is known, not when "ready".
                future = client.call_async(SetPen.Request(r=255, g=0, b=0, width=3, off=0))
    finally:
        probe.close()
    return seen


def watch(s, domain: int, names: list[str], seconds: float) -> None:
    """All turtles driven (as bench/scale.py does) and turtle_controller running: poll a
    SetPen client's service_is_ready() and the graph counts behind it every 20 ms."""
    from geometry_msgs.msg import Twist
    driver = TestNode(domain, 'driver')
    publishers = [driver.node.create_publisher(Twist, f'/{n}/cmd_vel', 7) for n in names]
    circle = Twist()
    circle.linear.x, circle.angular.z = 1.0, 1.0
    driver.node.create_timer(0.5, lambda: [p.publish(circle) for p in publishers])
    controller = s.start('my_robot_controller', 'turtle_controller')
    watcher = TestNode(domain, 'watcher')
    client = watcher.node.create_client(SetPen, '/turtle1/set_pen')
    gaps: list[tuple[float, float, str]] = []
    down_since = None
    detail = ''
    start = time.monotonic()
    try:
        while time.monotonic() - start < seconds:
            driver.executor.spin_once(timeout_sec=0.01)
            watcher.executor.spin_once(timeout_sec=0.01)
            now = time.monotonic() - start
            ready = client.service_is_ready()
            if not ready and down_since is None:
                down_since = now
                readers = len(watcher.node.get_subscriptions_info_by_topic(REQUEST_TOPIC,
                                                                           no_mangle=True))
                writers = len(watcher.node.get_publishers_info_by_topic(REPLY_TOPIC,
                                                                        no_mangle=True))
                detail = f'graph: {readers} request readers, {writers} reply writers'
            elif ready and down_since is not None:
                gaps.append((down_since, now, detail))
                down_since = None
    finally:
        watcher.close()
        driver.close()
    if down_since is not None:
        gaps.append((down_since, seconds, detail + ' (still down)'))
    warnings = controller.output.count('not available')
    print(f'watch {seconds:g} s: watcher saw set_pen not ready {len(gaps)} times; '
          f'controller warned {warnings} times')
    for begin, end, what in gaps[:20]:
        print(f'  not ready {begin:.2f}-{end:.2f} s ({end - begin:.2f} s) {what}')


def shutdown(sim, domain: int) -> None:
    """SIGINT turtlesim and watch set_pen from a fresh client until turtlesim has exited."""
    import signal
    watcher = TestNode(domain, 'shutdown_watcher')
    client = watcher.node.create_client(SetPen, '/turtle1/set_pen')
    try:
        deadline = time.monotonic() + 20
        while not client.service_is_ready() and time.monotonic() < deadline:
            watcher.executor.spin_once(timeout_sec=0.02)
        start = time.monotonic()
        import os
        os.killpg(sim.popen.pid, signal.SIGINT)
        not_ready = exited = None
        while time.monotonic() - start < 60 and (not_ready is None or exited is None):
            watcher.executor.spin_once(timeout_sec=0.02)
            now = time.monotonic() - start
            if not_ready is None and not client.service_is_ready():
                not_ready = now
            if exited is None and sim.popen.poll() is not None:
                exited = now
    finally:
        watcher.close()
    print(f'turtlesim SIGINT -> set_pen not ready {not_ready:.2f} s -> process exited '
          f'{exited:.2f} s')


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--turtles', type=int, default=200)
    parser.add_argument('--newcomers', type=int, default=3)
    parser.add_argument('--bound', type=float, default=30.0, help='seconds per newcomer')
    parser.add_argument('--shutdown', action='store_true',
                        help='finally SIGINT turtlesim and time its shutdown')
    parser.add_argument('--watch', type=float, default=30.0,
                        help='then seconds of driving with the controller, watched')
    args = parser.parse_args()
    with session('set_pen_ready') as s:
        sim = s.start('turtlesim', 'turtlesim_node', '--headless')
        sim.wait_for_output(r'Spawning turtle')
        spawner = s.probe('spawner')
        try:
            started = time.monotonic()
            names = spawn_all(spawner, args.turtles - 1)
            print(f'{len(names) + 1} turtles up in {time.monotonic() - started:.1f} s')
        finally:
            spawner.close()
        time.sleep(2.0)
        for i in range(args.newcomers):
            seen = newcomer(s.domain, args.bound)
            print(f'newcomer {i + 1}: ' + ', '.join(
                f'{k} {"never" if v is None else f"{v:.2f} s"}' for k, v in seen.items()))
        if args.watch > 0:
            watch(s, s.domain, names, args.watch)
        if args.shutdown:
            shutdown(sim, s.domain)
    return 0


if __name__ == '__main__':
    sys.exit(main())
