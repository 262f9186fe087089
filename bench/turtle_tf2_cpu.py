"""CPU of the tf2 turtle demo's nodes while turtle2 follows a circling turtle1.

    scripts/ws python bench/turtle_tf2_cpu.py [--seconds 30]

Runs `ros2 launch turtle_tf2_py turtle_tf2_demo.launch.py` as a learner does, keeps turtle1
driving in a circle (a Twist twice a second, as held arrow keys would), and reads each
node's user + system CPU time from /proc over the window. The listener receives both
turtles' frames on /tf (2 x 62.5 Hz) and looks one up once a second.
"""

from __future__ import annotations

import argparse
import re
import time

from common import Row, Session, cpu_seconds, session, verdict

WARM_UP_S = 5.0
DURATION_S = 30.0
PID_LINE = re.compile(r'\[INFO\] \[([\w-]+)-\d+\]: process started with pid \[(\d+)\]')
NODES = ('turtle_tf2_listener', 'turtle_tf2_broadcaster', 'turtlesim_node')


def run(current: Session, duration: float = DURATION_S) -> tuple[list[Row], dict]:
    from geometry_msgs.msg import Twist
    demo = current.start_argv(['ros2', 'launch', 'turtle_tf2_py', 'turtle_tf2_demo.launch.py'])
    demo.wait_for_output(r'Successfully spawned turtle2', timeout=60)
    pids: dict[str, int] = {}
    for name, pid in PID_LINE.findall(demo.output):
        pids[name if name not in pids else f'{name} (2)'] = int(pid)
    probe = current.probe()
    try:
        publisher = probe.node.create_publisher(Twist, '/turtle1/cmd_vel', 10)
        circle = Twist()
        circle.linear.x, circle.angular.z = 1.5, 0.8

        def drive(seconds: float) -> None:
            end = time.monotonic() + seconds
            while time.monotonic() < end:
                publisher.publish(circle)
                probe.spin_for(0.5)
        drive(WARM_UP_S)
        before = {name: cpu_seconds(pid) for name, pid in pids.items()}
        started = time.monotonic()
        drive(duration)
        elapsed = time.monotonic() - started
        percent = {name: 100 * (cpu_seconds(pid) - before[name]) / elapsed
                   for name, pid in pids.items()}
    finally:
        probe.close()
    rows = [Row('tf2 demo CPU', f'{name}, {elapsed:.0f} s of the turtle demo',
                f'{value:.1f} % of a core', '< 5 %' if name == 'turtle_tf2_listener' else '',
                verdict(value < 5.0) if name == 'turtle_tf2_listener' else '')
            for name, value in sorted(percent.items())]
    return rows, {'turtle_tf2_cpu': percent}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--seconds', type=float, default=DURATION_S)
    options = parser.parse_args()
    with session('turtle_tf2_cpu') as current:
        rows, _ = run(current, options.seconds)
    for row in rows:
        print(f'{row.metric}: {row.value} {row.target} {row.verdict}'.rstrip())


if __name__ == '__main__':
    main()
