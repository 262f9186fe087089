"""`ros2 run demo_nodes_cpp talker_serialized_message`: serializes each String itself, prints
the message and its CDR bytes (hex), and publishes the bytes on /chatter."""
import sys

from rclpy.node import Node
from rclpy.serialization import serialize_message
from std_msgs.msg import String

from demo_nodes_cpp.rclcpp_node import run_rclcpp_node


class SerializedMessageTalker(Node):
    def __init__(self) -> None:
        super().__init__('serialized_message_talker')
        self.count = 1
        self.pub = self.create_publisher(String, 'chatter', 7)
        self.timer = self.create_timer(1.0, self.on_timer)

    def on_timer(self) -> None:
        msg = String(data=f'Hello World:{self.count}')
        self.count += 1
        serialized = serialize_message(msg)
        # Printed, not logged, as upstream's printf.
        print(f'ROS message:\n{msg.data}\nserialized message:\n'
              + ''.join(f'{byte:02x} ' for byte in serialized), flush=True)
        self.pub.publish(serialized)


def main() -> int:
    return run_rclcpp_node(SerializedMessageTalker)


if __name__ == '__main__':
    sys.exit(main())
