"""The "Using time" page's listener, in Python: look up the transform at the current time.

Jazzy has this page for C++ only. Its two steps are the parameter `timeout` (seconds):

- `timeout:=0.0` asks for "now" without waiting: the newest transform is always a few
  milliseconds older, so every lookup fails with "Lookup would require extrapolation into
  the future" (the page's first step);
- `timeout:=0.05` (the default, the page's fix) waits up to 50 ms for the data to arrive.
"""

from __future__ import annotations

import sys

from geometry_msgs.msg import TransformStamped
from rclpy.duration import Duration

from turtle_tf2_py.parameters import declare_seconds
from turtle_tf2_py.turtle_tf2_listener import FrameListener, run

TIMEOUT_MAX = 1.0  # seconds: the lookup runs in the once-a-second timer


class UsingTimeFrameListener(FrameListener):
    waits_for_transforms = True

    def __init__(self) -> None:
        super().__init__()
        self.timeout = Duration(seconds=declare_seconds(self, 'timeout', 0.05, TIMEOUT_MAX))

    def lookup(self, to_frame: str, from_frame: str) -> TransformStamped:
        now = self.get_clock().now()
        return self.tf_buffer.lookup_transform(to_frame, from_frame, now, self.timeout)


def main() -> int:
    return run(UsingTimeFrameListener)


if __name__ == '__main__':
    sys.exit(main())
