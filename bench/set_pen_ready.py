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
from turtlesim.srv import SetPen, Spawn

from common import TestNode, session

REQUEST_TOPIC = 'rq/turtle1/set_penRequest'
REPLY_TOPIC = 'rr/turtle1/set_penReply'


def spawn_all(probe: TestNode, count: int) -> None:
    client = probe.node.create_client(Spawn, '/spawn')
    if not client.wait_for_service(timeout_sec=30):
        raise RuntimeError('no /spawn')
    futures = [client.call_async(Spawn.Request(x=1.0 + (i % 9), y=1.0 + (i // 9) % 9,
                                               theta=0.0, name=f't{i}')) for i in range(count)]
    deadline = time.monotonic() + 300
    while not all(f.done() for f in futures) and time.monotonic() < deadline:
        probe.executor.spin_once(timeout_sec=0.1)


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


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--turtles', type=int, default=200)
    parser.add_argument('--newcomers', type=int, default=3)
    parser.add_argument('--bound', type=float, default=30.0, help='seconds per newcomer')
    args = parser.parse_args()
    with session('set_pen_ready') as s:
        s.start('turtlesim', 'turtlesim_node', '--headless').wait_for_output(r'Spawning turtle')
        spawner = s.probe('spawner')
        try:
            started = time.monotonic()
            spawn_all(spawner, args.turtles - 1)
            print(f'{args.turtles} turtles up in {time.monotonic() - started:.1f} s')
        finally:
            spawner.close()
        time.sleep(2.0)
        for i in range(args.newcomers):
            seen = newcomer(s.domain, args.bound)
            print(f'newcomer {i + 1}: ' + ', '.join(
                f'{k} {"never" if v is None else f"{v:.2f} s"}' for k, v in seen.items()))
    return 0


if __name__ == '__main__':
    sys.exit(main())
