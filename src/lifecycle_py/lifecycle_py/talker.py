"""`ros2 run lifecycle_py lifecycle_talker`: the lifecycle demo's lc_talker as upstream's
rclpy port prints it (numbered from 0, its log lines, no pause in on_activate)."""

from __future__ import annotations

import sys

from lifecycle.lifecycle_talker import LifecycleTalker as RclcppLifecycleTalker
from lifecycle.lifecycle_talker import run


class LifecycleTalker(RclcppLifecycleTalker):
    FIRST_COUNT = 0
    INACTIVE_TEXT = 'Lifecycle publisher is inactive. Messages are not published.'
    CLEANUP_TEXT = 'on_cleanup() is called.'
    SHUTDOWN_TEXT = 'on_shutdown() is called.'
    ACTIVATE_SECONDS = 0.0


def main() -> int:
    return run(LifecycleTalker)


if __name__ == '__main__':
    sys.exit(main())
