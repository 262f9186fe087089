"""`ros2 run demo_nodes_cpp add_two_ints_server [--ros-args -p one_shot:=true]`: demo_nodes_py's
server; with `one_shot` it shuts down after its first request, as upstream's."""
import sys

import rclpy
from demo_nodes_py.services.add_two_ints_server import AddTwoIntsServer

from demo_nodes_cpp.rclcpp_node import run_rclcpp_node


class ServerNode(AddTwoIntsServer):
    def __init__(self) -> None:
        super().__init__()
        self.saw_request = False
        if self.declare_parameter('one_shot', False).value:
            self.timer = self.create_timer(0.1, self.on_timer)

    def on_request(self, request, response):
        self.saw_request = True
        return super().on_request(request, response)

    def on_timer(self) -> None:
        if self.saw_request:
            rclpy.try_shutdown()


def main() -> int:
    return run_rclcpp_node(ServerNode)


if __name__ == '__main__':
    sys.exit(main())
