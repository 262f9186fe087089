"""A small node for the `ros2` CLI tests: one of each kind of graph entity, predictable values.

Node `/cli_test_node`:
- services `/pen` (turtlesim/srv/SetPen, empty response) and
  `/flag` (std_srvs/srv/SetBool, answers success=data, message 'flag is <data>'), plus a hidden
  service `/_hidden_flag`; every request received is logged as `REQUEST <service> <repr>`;
- publisher `/pose` (turtlesim/msg/Pose, x=1.5 y=2.25 theta=-0.5 at 20 Hz, keep-last 7 reliable);
- subscription `/heard` (std_msgs/msg/String), logging `HEARD <data>`;
- parameters `speed` (int 69, range 0..255 step 1, described), `ratio` (double 0.5),
  `label` (string 'hello'), `enabled` (bool true).
Prints `READY` once everything exists.
"""

import rclpy
from rcl_interfaces.msg import IntegerRange, ParameterDescriptor
from rclpy.executors import ExternalShutdownException
from rclpy.node import Node
from rclpy.qos import QoSProfile
from std_msgs.msg import String
from std_srvs.srv import SetBool
from turtlesim.msg import Pose
from turtlesim.srv import SetPen


class CliTestNode(Node):
    def __init__(self) -> None:
        super().__init__('cli_test_node')
        self.declare_parameter('speed', 69, ParameterDescriptor(
            description='Speed of the test', integer_range=[
                IntegerRange(from_value=0, to_value=255, step=1)]))
        self.declare_parameter('ratio', 0.5)
        self.declare_parameter('label', 'hello')
        self.declare_parameter('enabled', True)
        self.create_service(SetPen, 'pen', self.on_pen)
        self.create_service(SetBool, 'flag', self.on_flag)
        self.create_service(SetBool, '_hidden_flag', self.on_flag)
        self.pose = self.create_publisher(Pose, 'pose', QoSProfile(depth=7))
        self.create_subscription(String, 'heard', self.on_heard, 10)
        self.create_timer(0.05, self.tick)

    def on_pen(self, request, response):
        print(f'REQUEST /pen {request!r}', flush=True)
        return response

    def on_flag(self, request, response):
        print(f'REQUEST /flag {request!r}', flush=True)
        response.success = request.data
        response.message = f'flag is {request.data}'
        return response

    def on_heard(self, msg: String) -> None:
        print(f'HEARD {msg.data}', flush=True)

    def tick(self) -> None:
        self.pose.publish(Pose(x=1.5, y=2.25, theta=-0.5))


def main() -> None:
    rclpy.init()
    node = CliTestNode()
    print('READY', flush=True)
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass
    finally:
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
