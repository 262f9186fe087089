"""The "Traveling in time" page's listener, in Python: follow where the target was 5 s ago.

Jazzy has this page for C++ only. Its two steps are the parameter `fixed_frame`:

- `fixed_frame:=''` asks "where was carrot1 5 s ago, relative to turtle2 5 s ago?"
  (`lookup_transform` at a past time): turtle2 drives around uncontrollably;
- `fixed_frame:=world` (the default, the page's fix) asks "where was carrot1 5 s ago,
  relative to turtle2 now?" through the frame that does not move, with
  `lookup_transform_full` (the C++ page's six-argument lookupTransform).

`delay` (seconds, default 5.0) is how far back; lookups wait up to 50 ms, as the page's.
"""

from __future__ import annotations

import sys

from geometry_msgs.msg import TransformStamped
from rclpy.duration import Duration

from turtle_tf2_py.parameters import declare_frame, declare_seconds
from turtle_tf2_py.turtle_tf2_listener import FrameListener, run

TIMEOUT = Duration(seconds=0.05)
DELAY_MAX = 9.0  # seconds: tf2 keeps 10 s of each frame by default


class TimeTravelFrameListener(FrameListener):
    waits_for_transforms = True

    def __init__(self) -> None:
        super().__init__()
        self.delay = Duration(seconds=declare_seconds(self, 'delay', 5.0, DELAY_MAX))
        self.fixed_frame = declare_frame(self, 'fixed_frame', 'world')

    def lookup(self, to_frame: str, from_frame: str) -> TransformStamped:
        now = self.get_clock().now()
        when = now - self.delay
        if not self.fixed_frame:
            return self.tf_buffer.lookup_transform(to_frame, from_frame, when, TIMEOUT)
        return self.tf_buffer.lookup_transform_full(
            target_frame=to_frame, target_time=now, source_frame=from_frame,
            source_time=when, fixed_frame=self.fixed_frame, timeout=TIMEOUT)


def main() -> int:
    return run(TimeTravelFrameListener)


if __name__ == '__main__':
    sys.exit(main())
