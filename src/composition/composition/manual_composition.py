"""`ros2 run composition manual_composition`: talker, listener, Server and Client in one
process and one executor. A remapping argument prefixed with a node's name
(`-r talker:__node:=my_talker`) applies to that node only (rcl matches the prefix)."""

from __future__ import annotations

import sys

from node_runtime.rclcpp_parity import declare_rclcpp_parameters
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.executors import SingleThreadedExecutor

from composition.components import Client, Listener, Server, Talker


def main() -> int:
    with ros_session() as stop:
        nodes = [Talker(), Listener(), Server(), Client()]
        executor = SingleThreadedExecutor()
        for node in nodes:
            declare_rclcpp_parameters(node)  # they are rclcpp nodes upstream
            executor.add_node(node)
        # spin_until_stopped spins the executor (all four nodes) until Ctrl-C.
        spin_until_stopped(nodes[0], stop, executor)
        for node in nodes[1:]:
            node.destroy_node()
    return 0


if __name__ == '__main__':
    sys.exit(main())
