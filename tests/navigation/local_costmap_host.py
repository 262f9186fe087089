"""A local costmap as its own process, for behavior_server's tests (upstream's runs inside
controller_server): nav2_costmap_2d's Costmap2DROS as `/local_costmap/local_costmap`,
configured and activated at once, publishing local_costmap/costmap_raw and
local_costmap/published_footprint.

Run with `--ros-args --params-file <file with a local_costmap: local_costmap: section>`.
"""

from __future__ import annotations

import sys

from nav2_costmap_2d.costmap_2d_ros import Costmap2DROS
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.executors import MultiThreadedExecutor
from rclpy.lifecycle import TransitionCallbackReturn


def main() -> int:
    with ros_session(sys.argv) as stop:
        node = Costmap2DROS('local_costmap', 'local_costmap')
        node.stop_event = stop
        if node.trigger_configure() != TransitionCallbackReturn.SUCCESS or \
                node.trigger_activate() != TransitionCallbackReturn.SUCCESS:
            print('local costmap failed to start', flush=True)
            return 1
        print('local costmap active', flush=True)
        spin_until_stopped(node, stop, MultiThreadedExecutor(num_threads=2))
    return 0


if __name__ == '__main__':
    sys.exit(main())
