"""`ros2 run demo_nodes_cpp listener_serialized_message`: takes /chatter as CDR bytes, prints
their length and hex, then the String they deserialize to."""
import sys

from rclpy.node import Node
from rclpy.serialization import deserialize_message
from std_msgs.msg import String

from demo_nodes_cpp.rclcpp_node import run_rclcpp_node


class SerializedMessageListener(Node):
    def __init__(self) -> None:
        super().__init__('serialized_message_listener')
        self.sub = self.create_subscription(String, 'chatter', self.on_chatter, 10, raw=True)

    def on_chatter(self, serialized: bytes) -> None:
        print(f'I heard data of length: {len(serialized)}\n'
              + ''.join(f'{byte:02x} ' for byte in serialized) + '\nserialized data after '
              f'deserialization: {deserialize_message(serialized, String).data}', flush=True)


def main() -> int:
    return run_rclcpp_node(SerializedMessageListener)


if __name__ == '__main__':
    sys.exit(main())
