"""The composition demo's four nodes (upstream: rclcpp components in one library each).

Their names, topics and log lines are upstream's; talker and listener are demo_nodes_cpp's
with the component's queue depth, the server is demo_nodes_py's with the component's line.
"""

from __future__ import annotations

from demo_nodes_cpp.topics.talker import Talker as DemoTalker
from demo_nodes_py.services.add_two_ints_server import AddTwoIntsServer
from demo_nodes_py.topics.listener import Listener as DemoListener
from example_interfaces.srv import AddTwoInts
from rclpy.node import Node
from rclpy.task import Future


class Talker(DemoTalker):
    QOS_DEPTH = 10


class Listener(DemoListener):
    pass


class Server(AddTwoIntsServer):
    def __init__(self) -> None:
        super().__init__('Server')

    def on_request(self, request: AddTwoInts.Request,
                   response: AddTwoInts.Response) -> AddTwoInts.Response:
        self.get_logger().info(f'Incoming request: [a: {request.a}, b: {request.b}]')
        response.sum = (request.a + request.b + 2**63) % 2**64 - 2**63  # int64 wraps
        return response


class Client(Node):
    """Asks the Server for 2 + 3 every 2 s; the answer is logged when it arrives."""

    def __init__(self) -> None:
        super().__init__('Client')
        self.client = self.create_client(AddTwoInts, 'add_two_ints')
        self.timer = self.create_timer(2.0, self.on_timer)

    def on_timer(self) -> None:
        if not self.client.wait_for_service(timeout_sec=1.0):
            self.get_logger().info('Service not available after waiting')
            return
        future = self.client.call_async(AddTwoInts.Request(a=2, b=3))
        future.add_done_callback(self.on_result)

    def on_result(self, future: Future) -> None:
        self.get_logger().info(f'Got result: [{future.result().sum}]')
