"""`ros2 run demo_nodes_py introspection`: an AddTwoInts service and a client calling it
every half second, in one process. Each publishes its service introspection events on
/add_two_ints/_service_event as its parameter `service_configure_introspection` /
`client_configure_introspection` says: disabled (default), metadata or contents."""
from __future__ import annotations

import sys

from example_interfaces.srv import AddTwoInts
from node_runtime.spinning import ros_session, spin_until_stopped
from rcl_interfaces.msg import SetParametersResult
from rclpy.client import Client
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from rclpy.qos import qos_profile_system_default
from rclpy.service import Service
from rclpy.service_introspection import ServiceIntrospectionState
from rclpy.task import Future

from demo_nodes_py.services.add_two_ints_server import AddTwoIntsServer

STATES = {
    'disabled': ServiceIntrospectionState.OFF,
    'metadata': ServiceIntrospectionState.METADATA,
    'contents': ServiceIntrospectionState.CONTENTS,
}


def introspection_parameter(node: Node, name: str, endpoint: Client | Service) -> None:
    """Declare `name`; a new value is checked before it is set and applied after."""

    def check(parameters: list[Parameter]) -> SetParametersResult:
        for parameter in parameters:
            if parameter.name != name:
                continue
            if parameter.type_ != Parameter.Type.STRING:
                return SetParametersResult(successful=False, reason='must be a string')
            if parameter.value not in STATES:
                return SetParametersResult(
                    successful=False,
                    reason="must be one of 'disabled', 'metadata', or 'contents'")
        return SetParametersResult(successful=True)

    def apply(parameters: list[Parameter]) -> None:
        for parameter in parameters:
            if parameter.name == name:
                endpoint.configure_introspection(node.get_clock(), qos_profile_system_default,
                                                 STATES[parameter.value])

    node.add_on_set_parameters_callback(check)
    node.add_post_set_parameters_callback(apply)
    node.declare_parameter(name, 'disabled')


class IntrospectionServiceNode(AddTwoIntsServer):
    def __init__(self) -> None:
        super().__init__('introspection_service')
        introspection_parameter(self, 'service_configure_introspection', self.srv)


class IntrospectionClientNode(Node):
    def __init__(self) -> None:
        super().__init__('introspection_client')
        self.cli = self.create_client(AddTwoInts, 'add_two_ints')
        introspection_parameter(self, 'client_configure_introspection', self.cli)
        self.in_progress = False
        self.timer = self.create_timer(0.5, self.on_timer)

    def on_timer(self) -> None:
        if self.in_progress or not self.cli.service_is_ready():
            return
        self.in_progress = True
        self.cli.call_async(AddTwoInts.Request(a=2, b=3)).add_done_callback(self.on_answer)

    def on_answer(self, future: Future) -> None:
        self.in_progress = False
        if future.result() is not None:
            self.get_logger().info(f'Result of add_two_ints: {future.result().sum}')
        else:
            self.get_logger().error(f'Exception calling service: {future.exception()!r}')


def main() -> int:
    with ros_session() as stop:
        executor = SingleThreadedExecutor()
        executor.add_node(IntrospectionServiceNode())
        spin_until_stopped(IntrospectionClientNode(), stop, executor)
    return 0


if __name__ == '__main__':
    sys.exit(main())
