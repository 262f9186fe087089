"""Subscribe to every turtle's pose in one process and count what arrives.

`python pose_sink.py COUNT_FILE NAME...`: one raw subscription per /<NAME>/pose (turtlesim's
QoS: reliable, keep-last 7) on rclpy's EventsExecutor; prints `subscribed` once all exist,
and on SIGINT writes {"received": n, "seconds": s} (counted from the first pose on) to
COUNT_FILE. bench/scale.py runs it to see how far "every pose published" gets when someone
takes every pose.
"""

from __future__ import annotations

import json
import signal
import sys
import threading
import time

import rclpy
from rclpy.experimental.events_executor import EventsExecutor
from rclpy.node import Node
from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
from rclpy.signals import SignalHandlerOptions
from turtlesim.msg import Pose

QOS = QoSProfile(depth=7, history=HistoryPolicy.KEEP_LAST,
                 reliability=ReliabilityPolicy.RELIABLE, durability=DurabilityPolicy.VOLATILE)


def main() -> None:
    out, names = sys.argv[1], sys.argv[2:]
    rclpy.init(signal_handler_options=SignalHandlerOptions.NO)
    node = Node('bench_pose_sink')
    count = [0]
    first = [0.0]
    silent = set(names)

    def on_pose(name: str) -> None:
        if silent:
            silent.discard(name)
            if not silent:
                first[0] = time.monotonic()
                count[0] = 0
                print('flowing', flush=True)
        count[0] += 1

    for name in names:
        node.create_subscription(Pose, f'/{name}/pose', lambda _raw, n=name: on_pose(n), QOS,
                                 raw=True)
    print('subscribed', flush=True)
    stop = threading.Event()
    signal.signal(signal.SIGINT, lambda *_: stop.set())
    executor = EventsExecutor()
    executor.add_node(node)
    while not stop.is_set():
        executor.spin_once(timeout_sec=0.1)
    seconds = time.monotonic() - first[0] if not silent else 0.0
    with open(out, 'w') as stream:
        json.dump({'received': count[0], 'seconds': seconds}, stream)
    executor.shutdown()
    node.destroy_node()
    rclpy.try_shutdown()


if __name__ == '__main__':
    main()
