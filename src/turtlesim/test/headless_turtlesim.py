"""A headless turtlesim_node process on a leased domain with an rclpy probe: what the
turtlesim_node tests (test_turtlesim_node*.py, fixtures in conftest.py) drive it with."""

from __future__ import annotations

import re
import time

from PySide6.QtGui import QImage
from rcl_interfaces.msg import Parameter, ParameterType, ParameterValue
from rcl_interfaces.srv import SetParameters
from std_srvs.srv import Trigger
from turtlesim.msg import Pose

from ws_testing import (
    RosProcess,
    TestNode,
    turtle_qos,
)

W = 11.088889122009277
CENTER = 5.544444561004639
BACKGROUND = (69, 86, 255)
PEN = (179, 184, 255)


class Sim:
    """The module's turtlesim process, an rclpy probe on its domain, and log bookkeeping."""

    def __init__(self, process: RosProcess, probe: TestNode, png) -> None:
        self.process = process
        self.probe = probe
        self.png = png
        self.mark = 0
        self._publishers = {}
        self._subscriptions = []

    # logs -----------------------------------------------------------------------------
    def new_output(self) -> str:
        return self.process.output[self.mark:]

    def wait_for_log(self, pattern: str, timeout: float = 5.0) -> re.Match[str]:
        deadline = time.monotonic() + timeout
        while True:
            match = re.search(pattern, self.new_output(), re.MULTILINE)
            if match:
                return match
            if time.monotonic() > deadline:
                raise AssertionError(f'{pattern!r} not logged; new output:\n{self.new_output()}')
            self.probe.spin_for(0.05)

    # ROS ---------------------------------------------------------------------------------
    def call(self, srv_type, service: str, **fields):
        return self.probe.call(srv_type, service, srv_type.Request(**fields))

    def collect(self, msg_type, topic: str, qos=None) -> list:
        received: list = []
        sub = self.probe.node.create_subscription(
            msg_type, topic, received.append, turtle_qos() if qos is None else qos)
        self._subscriptions.append(sub)
        return received

    def publish(self, topic: str, msg) -> None:
        if topic not in self._publishers:
            publisher = self.probe.node.create_publisher(type(msg), topic, turtle_qos())
            self._publishers[topic] = publisher
            self.probe.spin_until(lambda: publisher.get_subscription_count() > 0, 10,
                                  f'a subscriber on {topic}')
        self._publishers[topic].publish(msg)

    def latest_pose(self, turtle: str = 'turtle1', after: float = 0.1) -> Pose:
        """A pose published at least `after` seconds from now (so queued teleports applied)."""
        poses = self.collect(Pose, f'/{turtle}/pose')
        self.probe.spin_for(after)
        self.probe.spin_until(lambda: poses, 5, f'a pose of {turtle}')
        return poses[-1]

    def set_parameter(self, name: str, value: ParameterValue):
        return self.probe.call(SetParameters, '/turtlesim/set_parameters', SetParameters.Request(
            parameters=[Parameter(name=name, value=value)])).results[0]

    def canvas(self) -> QImage:
        response = self.call(Trigger, '/turtlesim/_save_canvas')
        assert response.success, response.message
        assert response.message == str(self.png)
        image = QImage(response.message)
        assert not image.isNull()
        return image

    def cleanup(self) -> None:
        for sub in self._subscriptions:
            self.probe.node.destroy_subscription(sub)
        self._subscriptions.clear()


def rgb(image: QImage, x: int, y: int) -> tuple[int, int, int]:
    color = image.pixelColor(x, y)
    return color.red(), color.green(), color.blue()


def int_value(value: int) -> ParameterValue:
    return ParameterValue(type=ParameterType.PARAMETER_INTEGER, integer_value=value)

