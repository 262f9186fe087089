"""What cam2image and showimage share: their QoS parameters, the web view of a topic, main()."""

from __future__ import annotations

import os
import re
import sys
import tempfile
import urllib.parse
from collections.abc import Callable
from pathlib import Path
from typing import Any

from node_runtime.spinning import ros_session, spin_until_stopped
from rcl_interfaces.msg import ParameterDescriptor
from rclpy.exceptions import InvalidParameterTypeException
from rclpy.logging import get_logger
from rclpy.node import Node
from rclpy.qos import HistoryPolicy, QoSProfile, ReliabilityPolicy

RELIABILITY = {'reliable': ReliabilityPolicy.RELIABLE,
               'best_effort': ReliabilityPolicy.BEST_EFFORT}
HISTORY = {'keep_all': HistoryPolicy.KEEP_ALL, 'keep_last': HistoryPolicy.KEEP_LAST}


class BadParameter(ValueError):
    """A parameter value the node cannot run with: its message is the one line to print."""


def declare_qos(node: Any, role: str) -> QoSProfile:
    """reliability, history and depth as upstream's nodes declare them; BadParameter when a
    value is not one of the allowed ones."""
    reliability = node.declare_parameter('reliability', 'reliable', ParameterDescriptor(
        description=f'Reliability QoS setting for the image {role}',
        additional_constraints='Must be one of: ' + ''.join(f'{k} ' for k in RELIABILITY)))
    history = node.declare_parameter('history', 'keep_all', ParameterDescriptor(
        description=f'History QoS setting for the image {role}',
        additional_constraints='Must be one of: ' + ''.join(f'{k} ' for k in HISTORY)))
    depth = node.declare_parameter('depth', 10).value
    if reliability.value not in RELIABILITY:
        raise BadParameter(f"Invalid QoS reliability setting '{reliability.value}'")
    if history.value not in HISTORY:
        raise BadParameter(f"Invalid QoS history setting '{history.value}'")
    if not isinstance(depth, int) or depth < 1:
        raise BadParameter(f"Invalid QoS depth setting '{depth}': must be a positive integer")
    return QoSProfile(history=HISTORY[history.value], depth=depth,
                      reliability=RELIABILITY[reliability.value])


def wants_help(usage: str) -> bool:
    """-h/--help before --ros-args: print the node's usage (upstream's text) and say so."""
    args = sys.argv[1:]
    own = args[:args.index('--ros-args')] if '--ros-args' in args else args
    if '-h' in own or '--help' in own:
        print(usage)
        return True
    return False


def run_node(make_node: Callable[[], Node], name: str, usage: str,
             refused: tuple[type[Exception], ...]) -> int:
    """main() of an image_tools node: its usage on -h, one logged line and exit 1 for a
    setting it refuses (`refused`, or a parameter value of the wrong type), else spin until
    Ctrl-C."""
    if wants_help(usage):
        return 0
    with ros_session() as stop:
        try:
            node = make_node()
        except (*refused, InvalidParameterTypeException) as error:
            get_logger(name).error(str(error))
            return 1
        spin_until_stopped(node, stop)
    return 0


def web_view(window: str, topic: str, qos: QoSProfile) -> str:
    """The URL of a page of the rqt web app (started if need be) that shows `topic`'s images
    under the name `window`, subscribed with `qos`'s reliability (the node's window)."""
    from rqt_web import instance
    reliability = 'Best Effort' if qos.reliability == ReliabilityPolicy.BEST_EFFORT else 'Reliable'
    folder = Path(tempfile.gettempdir()) / f'image_tools-{os.getuid()}'
    folder.mkdir(mode=0o700, exist_ok=True)
    config = folder / (re.sub(r'[^A-Za-z0-9_.-]', '_', window).strip('_') + '.rviz')
    # An RViz page with one Image display: the page draws each frame on a canvas.
    config.write_text(
        'Visualization Manager:\n'
        '  Global Options: {Fixed Frame: camera_frame}\n'
        '  Displays:\n'
        f'    - {{Class: rviz_default_plugins/Image, Name: "{window}", Enabled: true, '
        f'Value: true, Topic: {{Value: "{topic}", Reliability Policy: {reliability}}}}}\n')
    server, _ = instance.ensure_running()
    return server.url('rviz') + '&config=' + urllib.parse.quote(str(config))
