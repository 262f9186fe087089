"""`ros2 run image_tools showimage`: subscribes to `image` and logs 'Received image
#<frame_id>' for each frame (also on stderr, as upstream); with show_image (default) the
frames appear on a page of the rqt web app, whose URL it logs, instead of an OpenCV window."""

from __future__ import annotations

import sys

from rclpy.node import Node
from sensor_msgs.msg import Image

from image_tools.qos import BadParameter, declare_qos, run_node, web_view

USAGE = """Usage: showimage [-h] [--ros-args [-p param:=value] ...]
Subscribe to an image topic and show the images.
Example: ros2 run image_tools showimage --ros-args -p reliability:=best_effort
Options:
  -h, --help\tDisplay this help message and exit
Parameters:
  reliability\tReliability QoS setting. Either 'reliable' (default) or 'best_effort'
  history\tHistory QoS setting. Either 'keep_last' (default) or 'keep_all'.
\t\tIf 'keep_last', then up to N samples are stored where N is the depth
  depth\t\tDepth of the publisher queue. Only honored if history QoS is 'keep_last'. \
Default value is 10
  show_image\tShow the image. Either 'true' (default) or 'false'
  window_name\tName of the display window. Default value is the topic name"""

TOPIC = 'image'


class ShowImage(Node):
    def __init__(self) -> None:
        super().__init__('showimage')
        qos = declare_qos(self, 'subscription')
        show_image = self.declare_parameter('show_image', True).value
        window = self.declare_parameter('window_name', '').value
        self.get_logger().info(f"Subscribing to topic '{TOPIC}'")
        sub = self.create_subscription(Image, TOPIC, self._on_image, qos)
        if show_image:
            url = web_view(window or sub.topic_name, sub.topic_name, qos)
            self.get_logger().info(f'Showing the images at {url}')

    def _on_image(self, msg: Image) -> None:
        self.get_logger().info(f'Received image #{msg.header.frame_id}')
        print(f'Received image #{msg.header.frame_id}', file=sys.stderr, flush=True)


def main() -> int:
    return run_node(ShowImage, 'showimage', USAGE, (BadParameter,))


if __name__ == '__main__':
    sys.exit(main())
