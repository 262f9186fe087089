"""controller_server's control loop next to the simulator: the warehouse world at real-time
factor 1, map_server, a static map -> odom, planner_server and controller_server (the
parameters of tests/navigation/test_controller_server_sim.py: MPPI with time_steps 56 and
batch_size 2000 as Nav2's params file has it, and RPP) on sim time. The robot follows
planned paths round the centre pillar and back, `--laps` times, with the chosen controller.
Figures: the period between the /cmd_vel commands a subscriber receives while a goal runs
(p50 / p99 / max; target 20 Hz, p99 <= 75 ms), and controller_server's CPU share.

`python bench/controller_loop.py [--laps N] [--controller FollowPath|RPP] [--set NAME=VALUE]`
(--set changes a FollowPath parameter, e.g. --set batch_size=1000).
"""

from __future__ import annotations

import argparse
import math
import re
import sys
import time
from itertools import pairwise
from pathlib import Path

from common import BENCH, Row, Session, cpu_seconds, percentile, session, verdict

sys.path.insert(0, str(BENCH.parent / 'tests' / 'navigation'))
from test_controller_server_sim import PARAMS, SPAWN

BOUND = 60.0  # s: start-up or a lap slower than this is a failure, not a figure
TARGET_P99 = 0.075


def lap_goals() -> list[tuple[float, float, float]]:
    return [(5.5, 0.25, 0.0), (SPAWN[0], SPAWN[1], math.pi)]


def drive(current: Session, laps: int, controller: str, extra: dict[str, str]) -> dict:
    from ament_index_python.packages import get_package_share_directory
    from geometry_msgs.msg import PoseStamped, Twist
    from nav2_msgs.action import ComputePathToPose, FollowPath
    from rclpy.action import ActionClient
    world_map = Path(get_package_share_directory('mujoco_sim')) / 'maps' / 'warehouse.yaml'
    text = PARAMS.format(map=world_map)
    for name, value in extra.items():  # FollowPath's own parameters sit 6 spaces in
        text = re.sub(rf'\n      {name}: .*\n', '\n', text, count=1)
        text = text.replace('      plugin: "nav2_mppi_controller::MPPIController"\n',
                            '      plugin: "nav2_mppi_controller::MPPIController"\n'
                            f'      {name}: {value}\n', 1)
    params = current.log_dir / 'nav2_params.yaml'
    params.write_text(text)
    current.start_argv(['ros2', 'launch', 'diffbot_bringup', 'diffbot_sim.launch.py',
                        'world:=warehouse.xml', 'rviz:=false', 'real_time_factor:=1.0',
                        f'x:={SPAWN[0]}', f'y:={SPAWN[1]}', f'yaw:={SPAWN[2]}'])
    current.start('tf2_ros', 'static_transform_publisher', '--x', str(SPAWN[0]), '--y',
                  str(SPAWN[1]), '--yaw', str(SPAWN[2]), '--frame-id', 'map',
                  '--child-frame-id', 'odom')
    current.start('nav2_map_server', 'map_server', '--ros-args', '--params-file', str(params))
    current.start('nav2_planner', 'planner_server', '--ros-args', '--params-file', str(params))
    server = current.start('nav2_controller', 'controller_server', '--ros-args',
                           '--params-file', str(params))
    manager = current.start('nav2_lifecycle_manager', 'lifecycle_manager', '--ros-args',
                            '--params-file', str(params))
    manager.wait_for_output('Managed nodes are active', timeout=BOUND)
    probe = current.probe()
    arrivals: list[float] = []
    periods: list[float] = []
    outcomes: list[int] = []
    try:
        node = probe.node
        node.create_subscription(Twist, '/cmd_vel', lambda _m: arrivals.append(time.monotonic()),
                                 100)
        planner = ActionClient(node, ComputePathToPose, '/compute_path_to_pose')
        follower = ActionClient(node, FollowPath, '/follow_path')
        if not (planner.wait_for_server(timeout_sec=BOUND) and
                follower.wait_for_server(timeout_sec=BOUND)):
            raise TimeoutError('planner_server or controller_server did not appear')
        wall0, cpu0 = time.monotonic(), cpu_seconds(server.popen.pid)
        for _ in range(laps):
            for x, y, yaw in lap_goals():
                goal = PoseStamped()
                goal.header.frame_id = 'map'
                goal.pose.position.x, goal.pose.position.y = x, y
                goal.pose.orientation.z, goal.pose.orientation.w = math.sin(yaw / 2), \
                    math.cos(yaw / 2)
                future = planner.send_goal_async(ComputePathToPose.Goal(goal=goal))
                probe.spin_until(future.done, BOUND, 'the planner')
                planned = future.result().get_result_async()
                probe.spin_until(planned.done, BOUND, 'the plan')
                path = planned.result().result.path
                sent = follower.send_goal_async(FollowPath.Goal(
                    path=path, controller_id=controller, goal_checker_id='general_goal_checker'))
                probe.spin_until(sent.done, BOUND, 'follow_path')
                arrivals.clear()
                result = sent.result().get_result_async()
                probe.spin_until(result.done, BOUND, 'the end of the path')
                outcomes.append(result.result().status)
                # the last arrival is the zero velocity of the goal's end: not a cycle
                periods += [b - a for a, b in pairwise(arrivals[:-1])]
        wall, cpu = time.monotonic() - wall0, cpu_seconds(server.popen.pid) - cpu0
    finally:
        probe.close()
    return {'periods': periods, 'cpu': cpu / wall, 'succeeded': outcomes.count(4),
            'goals': len(outcomes), 'missed_lines': server.output.count('missed its desired')}


def run(current: Session, laps: int = 2, controller: str = 'FollowPath',
        extra: dict[str, str] | None = None) -> tuple[list[Row], dict]:
    extra = extra or {}
    r = drive(current, laps, controller, extra)
    p = r['periods']
    p50, p99, worst = (percentile(p, q) * 1000 for q in (50, 99, 100))
    label = f'{controller}' + ''.join(f', {k} {v}' for k, v in extra.items())
    rows = [
        Row('controller_loop', f'{label}: /cmd_vel period p50 / p99 / max over {len(p)} '
            f'cycles ({r["succeeded"]} of {r["goals"]} goals reached)',
            f'{p50:.1f} / {p99:.1f} / {worst:.1f} ms', 'p99 <= 75 ms',
            verdict(p99 <= TARGET_P99 * 1000 and r['succeeded'] == r['goals'])),
        Row('controller_loop', f'{label}: controller_server CPU (one core); "missed its '
            'desired rate" lines', f'{r["cpu"] * 100:.0f} %; {r["missed_lines"]}'),
    ]
    return rows, {'controller_loop': r}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--laps', type=int, default=2)
    parser.add_argument('--controller', default='FollowPath', choices=('FollowPath', 'RPP'))
    parser.add_argument('--set', action='append', default=[], metavar='NAME=VALUE')
    options = parser.parse_args()
    extra = {'batch_size': '2000', **dict(item.split('=', 1) for item in options.set)}
    with session('controller_loop') as current:
        rows, _ = run(current, options.laps, options.controller, extra)
    for row in rows:
        print(f'{row.metric}: {row.value} {row.target} {row.verdict}')


if __name__ == '__main__':
    main()
