"""The command line of talker_qos and listener_qos: `--reliable` and `-n N` (cycles)."""
from __future__ import annotations

import argparse
import threading
from collections.abc import Callable

import rclpy
from node_runtime.spinning import SIGNAL_CHECK_PERIOD
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.qos import QoSProfile, QoSReliabilityPolicy, qos_profile_sensor_data
from rclpy.utilities import remove_ros_args


def parse(argv: list[str], cycles_help: str) -> tuple[argparse.Namespace, QoSProfile]:
    """The options (ROS arguments left out) and the profile they choose: reliable with
    depth 10, or the sensor-data profile (best effort) by default, as upstream."""
    parser = argparse.ArgumentParser(formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    parser.add_argument('--reliable', action='store_true', help='set qos profile to reliable')
    parser.add_argument('-n', '--number_of_cycles', type=int, default=20, help=cycles_help)
    args = parser.parse_args(remove_ros_args(args=argv)[1:])
    if args.reliable:
        return args, QoSProfile(depth=10, reliability=QoSReliabilityPolicy.RELIABLE)
    return args, qos_profile_sensor_data


def describe(profile: QoSProfile) -> str:
    return 'Reliable' if profile.reliability == QoSReliabilityPolicy.RELIABLE else 'Best effort'


def spin_cycles(node: Node, cycles: int, callbacks_run: Callable[[], int],
                stop: threading.Event) -> None:
    """Spin until `cycles` callbacks have run (upstream: that many blocking spin_once calls),
    Ctrl-C or shutdown. Short waits, so that a Ctrl-C is noticed between messages."""
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    try:
        while callbacks_run() < cycles and not stop.is_set() and rclpy.ok():
            executor.spin_once(timeout_sec=SIGNAL_CHECK_PERIOD)
    finally:
        executor.shutdown(timeout_sec=1.0)
        node.destroy_node()
