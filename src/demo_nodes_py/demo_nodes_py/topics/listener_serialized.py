"""`ros2 run demo_nodes_py listener_serialized`: /chatter taken as serialized CDR bytes
(`raw=True`), logged as Python prints bytes."""
import sys

from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.node import Node
from std_msgs.msg import String


class SerializedSubscriber(Node):
    def __init__(self) -> None:
        super().__init__('serialized_subscriber')
        self.subscription = self.create_subscription(String, 'chatter', self.on_chatter, 10,
                                                     raw=True)

    def on_chatter(self, msg: bytes) -> None:
        self.get_logger().info(f'I heard: "{msg}"')


def main() -> int:
    with ros_session() as stop:
        spin_until_stopped(SerializedSubscriber(), stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
