"""`ros2 run demo_nodes_py talker`: 'Hello World: <n>' on /chatter once a second."""
import sys

from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.node import Node
from rclpy.qos import QoSProfile
from std_msgs.msg import String


class Talker(Node):
    # What differs from demo_nodes_cpp's talker, which subclasses this one.
    FIRST_COUNT = 0
    QOS_DEPTH = 10
    LOG_LINE = 'Publishing: "{}"'

    def __init__(self, name: str = 'talker', qos: QoSProfile | int | None = None) -> None:
        super().__init__(name)
        self.count = self.FIRST_COUNT
        self.pub = self.create_publisher(String, 'chatter',
                                         self.QOS_DEPTH if qos is None else qos)
        self.timer = self.create_timer(1.0, self.on_timer)

    def on_timer(self) -> None:
        msg = String(data=f'Hello World: {self.count}')
        self.count += 1
        self.get_logger().info(self.LOG_LINE.format(msg.data))
        self.pub.publish(msg)


def main() -> int:
    with ros_session() as stop:
        spin_until_stopped(Talker(), stop)
    return 0


if __name__ == '__main__':
    sys.exit(main())
