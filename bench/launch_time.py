"""Launch time: `ros2 launch turtlesim multisim.launch.py` until both turtlesims are
discoverable by an already running rclpy node, and Ctrl-C until `ros2 launch` has exited."""

from __future__ import annotations

import os
import signal
import time

from common import Row, Session, percentile

REPEATS = 5
NODES = {'/turtlesim1/turtlesim', '/turtlesim2/turtlesim'}


def run(session: Session, repeats: int = REPEATS) -> tuple[list[Row], dict]:
    probe = session.probe()
    up: list[float] = []
    down: list[float] = []
    try:
        for _ in range(repeats):
            started = time.monotonic()
            launch = session.start_argv(['ros2', 'launch', 'turtlesim', 'multisim.launch.py'])
            probe.spin_until(lambda: NODES <= set(probe.node.get_fully_qualified_node_names()),
                             60, 'both multisim turtlesims')
            up.append(time.monotonic() - started)
            stopping = time.monotonic()
            os.killpg(launch.popen.pid, signal.SIGINT)
            launch.wait(timeout=30)
            down.append(time.monotonic() - stopping)
            # the next round must not see this round's nodes
            probe.spin_until(lambda: not NODES & set(probe.node.get_fully_qualified_node_names()),
                             30, 'the turtlesims to leave the graph')
    finally:
        probe.close()
    rows = [
        Row('launch', f'multisim: ros2 launch to both nodes discoverable, p50 / max of {repeats}',
            f'{percentile(up, 50):.2f} / {max(up):.2f} s'),
        Row('launch', f'multisim: Ctrl-C to ros2 launch exited, p50 / max of {repeats}',
            f'{percentile(down, 50):.2f} / {max(down):.2f} s'),
    ]
    return rows, {'launch': {'up_s': up, 'down_s': down}}
