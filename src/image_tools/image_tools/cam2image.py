"""`ros2 run image_tools cam2image --ros-args -p burger_mode:=True`: publishes frames as
sensor_msgs/Image (bgr8) on `image` at `frequency` Hz, logging 'Publishing image #n'.

Upstream grabs them from a camera through OpenCV; this stand-in has no camera support and
says so, so burger_mode is the way to run it. `flip_image` (std_msgs/Bool) mirrors the
frames; show_camera shows them on a page of the rqt web app as showimage does.
"""

from __future__ import annotations

import sys

import numpy as np
from rclpy.node import Node
from rclpy.qos import qos_profile_sensor_data
from sensor_msgs.msg import Image
from std_msgs.msg import Bool

from image_tools.burger import Burger
from image_tools.qos import BadParameter, declare_qos, run_node, web_view

USAGE = """Usage: cam2image [-h] [--ros-args [-p param:=value] ...]
Publish images from a camera stream.
Example: ros2 run image_tools cam2image --ros-args -p reliability:=best_effort
Options:
  -h, --help\tDisplay this help message and exit
Parameters:
  reliability\tReliability QoS setting. Either 'reliable' (default) or 'best_effort'
  history\tHistory QoS setting. Either 'keep_last' (default) or 'keep_all'.
\t\tIf 'keep_last', then up to N samples are stored where N is the depth
  depth\t\tDepth of the publisher queue. Only honored if history QoS is 'keep_last'. \
Default value is 10
  frequency\tPublish frequency in Hz. Default value is 30
  burger_mode\tProduce images of burgers rather than connecting to a camera
  show_camera\tShow camera stream. Either 'true' or 'false' (default)
  device_id\tDevice ID of the camera. 0 (default) selects the default camera device.
  width\t\tWidth component of the camera stream resolution. Default value is 320
  height\tHeight component of the camera stream resolution. Default value is 240
  frame_id\t\tID of the sensor frame. Default value is 'camera_frame'
Note: try running v4l2-ctl --list-formats-ext to obtain a list of valid values."""


class Cam2Image(Node):
    def __init__(self) -> None:
        super().__init__('cam2image')
        qos = declare_qos(self, 'publisher')
        frequency = self.declare_parameter('frequency', 30.0).value
        show_camera = self.declare_parameter('show_camera', False).value
        self.declare_parameter('device_id', 0)
        self._width = self.declare_parameter('width', 320).value
        self._height = self.declare_parameter('height', 240).value
        burger_mode = self.declare_parameter('burger_mode', False).value
        self._frame_id = self.declare_parameter('frame_id', 'camera_frame').value
        if not isinstance(frequency, (int, float)) or not 0 < frequency <= 1000:
            raise BadParameter(f"Invalid frequency '{frequency}': must be a number of Hz "
                               'above 0, at most 1000')
        if not burger_mode:
            raise BadParameter('Could not open video stream (this cam2image has no camera '
                               'support: run it with -p burger_mode:=True)')
        self._burger = Burger()
        self._burger.render_burger(self._width, self._height)  # refuses a size too small
        self._flipped = False
        self._count = 1
        self._pub = self.create_publisher(Image, 'image', qos)
        self.create_subscription(Bool, 'flip_image', self._on_flip, qos_profile_sensor_data)
        if show_camera:
            self.get_logger().info(f"Showing the camera stream at "
                                   f"{web_view('cam2image', self._pub.topic_name, qos)}")
        self.create_timer(1.0 / frequency, self._tick)

    def _on_flip(self, msg: Bool) -> None:
        self._flipped = msg.data
        self.get_logger().info(f"Set flip mode to: {'on' if self._flipped else 'off'}")

    def _tick(self) -> None:
        frame = self._burger.render_burger(self._width, self._height)
        if self._flipped:
            frame = np.ascontiguousarray(frame[:, ::-1])
        msg = Image(height=self._height, width=self._width, encoding='bgr8', is_bigendian=0,
                    step=self._width * 3, data=frame.tobytes())
        msg.header.frame_id = self._frame_id
        msg.header.stamp = self.get_clock().now().to_msg()
        self.get_logger().info(f'Publishing image #{self._count}')
        self._count += 1
        self._pub.publish(msg)


def main() -> int:
    # BadParameter, a burger that does not fit (ValueError both)
    return run_node(Cam2Image, 'cam2image', USAGE, (ValueError,))


if __name__ == '__main__':
    sys.exit(main())
