"""`ros2 run demo_nodes_py listener`: logs each String heard on /chatter."""
import sys

from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.node import Node
from rclpy.qos import QoSProfile
from std_msgs.msg import String


class Listener(Node):
    def __init__(self, name: str = 'listener', qos: QoSProfile | int = 10) -> None:
        super().__init__(name)
        self.heard = 0  # listener_qos stops after a number of messages
        self.sub = self.create_subscription(String, 'chatter', self.on_chatter, qos)

    def on_chatter(self, msg: String) -> None:
        self.heard += 1
        self.get_logger().info(f'I heard: [{msg.data}]')


def main() -> int:
    with ros_session() as stop:
        spin_until_stopped(Listener(), stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
