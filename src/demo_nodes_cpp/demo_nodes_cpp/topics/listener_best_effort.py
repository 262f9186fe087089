"""`ros2 run demo_nodes_cpp listener_best_effort`: the listener (same node name) with the
sensor-data QoS (best effort, depth 5)."""
import sys

from demo_nodes_py.topics.listener import Listener
from rclpy.qos import qos_profile_sensor_data

from demo_nodes_cpp.rclcpp_node import run_rclcpp_node


def main() -> int:
    return run_rclcpp_node(lambda: Listener(qos=qos_profile_sensor_data))


if __name__ == '__main__':
    sys.exit(main())
