"""AMCL on the simulated robot: the warehouse world at real-time factor 1, map_server, amcl
and a lifecycle_manager on sim time; after an /initialpose 0.25 m / 0.1 rad off the truth,
two minutes of driving a loop (a 1.5 m circle clear of the shelves). Figures: AMCL's RMS and
maximum position error against /ground_truth/odom at each amcl_pose's stamp (and its mean
along and across the robot's heading: an offset shows there), the scans amcl answered with a
map -> odom transform per scan received, its filter updates per second, and its CPU share.

`python bench/amcl_drive.py [--seconds S] [--update-min-d D] [--update-min-a A]
[--set NAME=VALUE]...` (d = a = 0: every scan is a filter update).
Targets (Nav2 issue): RMS <= 5 cm; every scan handled.
"""

from __future__ import annotations

import argparse
import math
import time
from pathlib import Path

from common import Row, Session, cpu_seconds, session, verdict

SECONDS = 120.0  # of sim time driving
DRIVE = (0.3, -0.2)  # m/s, rad/s: clockwise around (0, -1.5), >= 1 m from any obstacle
START_ERROR = (0.2, -0.15, 0.1)
BOUND = 60.0  # s: start-up slower than this is a failure, not a figure
PARAMS = """\
amcl:
  ros__parameters:
    use_sim_time: true
    alpha1: 0.05
    alpha2: 0.05
    alpha3: 0.05
    alpha4: 0.05
    base_frame_id: base_footprint
    odom_frame_id: odom
    global_frame_id: map
    scan_topic: scan
    laser_model_type: likelihood_field
    update_min_d: {update_min_d}
    update_min_a: {update_min_a}
{extra}map_server:
  ros__parameters:
    use_sim_time: true
    yaml_filename: {map}
lifecycle_manager:
  ros__parameters:
    use_sim_time: true
    autostart: true
    node_names: ['map_server', 'amcl']
"""


def _yaw(q) -> float:
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


def _seconds(stamp) -> float:
    return stamp.sec + stamp.nanosec * 1e-9


def drive(current: Session, seconds: float, update_min_d: float, update_min_a: float,
          extra: dict[str, str]) -> dict:
    from ament_index_python.packages import get_package_share_directory
    from geometry_msgs.msg import PoseWithCovarianceStamped, Twist
    from nav_msgs.msg import Odometry
    from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
    from sensor_msgs.msg import LaserScan
    from tf2_msgs.msg import TFMessage
    world_map = Path(get_package_share_directory('mujoco_sim')) / 'maps' / 'warehouse.yaml'
    params = current.log_dir / 'nav2_params.yaml'
    params.write_text(PARAMS.format(map=world_map, update_min_d=update_min_d,
                                    update_min_a=update_min_a,
                                    extra=''.join(f'    {k}: {v}\n' for k, v in extra.items())))
    current.start_argv(['ros2', 'launch', 'diffbot_bringup', 'diffbot_sim.launch.py',
                        'world:=warehouse.xml', 'rviz:=false', 'real_time_factor:=1.0'])
    current.start('nav2_map_server', 'map_server', '--ros-args', '--params-file', str(params))
    amcl = current.start('nav2_amcl', 'amcl', '--ros-args', '--params-file', str(params))
    manager = current.start('nav2_lifecycle_manager', 'lifecycle_manager', '--ros-args',
                            '--params-file', str(params))
    manager.wait_for_output('Managed nodes are active', timeout=BOUND)
    amcl.wait_for_output(r'Received a \d+ X \d+ map', timeout=BOUND)
    probe = current.probe()
    latched = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                         reliability=ReliabilityPolicy.RELIABLE)
    try:
        node = probe.node
        truths = probe.collect(Odometry, '/ground_truth/odom', 1000)
        poses = probe.collect(PoseWithCovarianceStamped, '/amcl_pose', latched)
        scans: list[float] = []
        node.create_subscription(LaserScan, '/scan',
                                 lambda m: scans.append(_seconds(m.header.stamp)), 50)
        answered: list[float] = []
        node.create_subscription(TFMessage, '/tf', lambda m: answered.extend(
            _seconds(t.header.stamp) for t in m.transforms if t.child_frame_id == 'odom'), 100)
        initial_pub = node.create_publisher(PoseWithCovarianceStamped, '/initialpose', 10)
        cmd_pub = node.create_publisher(Twist, '/cmd_vel', 10)
        probe.spin_until(lambda: truths and initial_pub.get_subscription_count() > 0, BOUND,
                         'the ground truth and amcl')
        start = truths[-1].pose.pose
        yaw0 = _yaw(start.orientation) + START_ERROR[2]
        initial = PoseWithCovarianceStamped()
        initial.header.frame_id = 'map'
        initial.pose.pose.position.x = start.position.x + START_ERROR[0]
        initial.pose.pose.position.y = start.position.y + START_ERROR[1]
        initial.pose.pose.orientation.z = math.sin(yaw0 / 2)
        initial.pose.pose.orientation.w = math.cos(yaw0 / 2)
        cov = [0.0] * 36
        cov[0] = cov[7] = 0.25 ** 2
        cov[35] = 0.15 ** 2
        initial.pose.covariance = cov
        initial_pub.publish(initial)
        amcl.wait_for_output('initialPoseReceived', timeout=10)
        twist = Twist()
        twist.linear.x, twist.angular.z = DRIVE
        node.create_timer(0.1, lambda: cmd_pub.publish(twist))
        t0 = _seconds(truths[-1].header.stamp)
        scans.clear()
        answered.clear()
        poses.clear()
        wall0, cpu0 = time.monotonic(), cpu_seconds(amcl.popen.pid)
        probe.spin_until(lambda: _seconds(truths[-1].header.stamp) > t0 + seconds,
                         seconds * 3 + BOUND, f'{seconds:g} s of sim time driving')
        wall, cpu = time.monotonic() - wall0, cpu_seconds(amcl.popen.pid) - cpu0
    finally:
        probe.close()
    by_stamp = {round(_seconds(m.header.stamp), 3): m.pose.pose for m in truths}
    errors, along, across, map_dx, map_dy = [], [], [], [], []
    for estimate in poses:
        truth = by_stamp.get(round(_seconds(estimate.header.stamp), 3))
        if truth is None:
            continue
        dx = estimate.pose.pose.position.x - truth.position.x
        dy = estimate.pose.pose.position.y - truth.position.y
        heading = _yaw(truth.orientation)
        errors.append(math.hypot(dx, dy))
        map_dx.append(dx)
        map_dy.append(dy)
        along.append(dx * math.cos(heading) + dy * math.sin(heading))
        across.append(-dx * math.sin(heading) + dy * math.cos(heading))
    # the first seconds converge from the initial pose's error: the RMS is over the rest
    settled = errors[len(errors) // 10:]
    rms = math.sqrt(sum(e * e for e in settled) / len(settled)) if settled else float('nan')
    handled = len(set(answered)) / max(1, len(scans))
    return {'rms': rms, 'max': max(settled, default=float('nan')), 'updates': len(poses),
            'matched': len(errors), 'along': sum(along) / max(1, len(along)),
            'across': sum(across) / max(1, len(across)),
            'dx': sum(map_dx) / max(1, len(map_dx)), 'dy': sum(map_dy) / max(1, len(map_dy)),
            'scans': len(scans),
            'handled': handled, 'update_rate': len(poses) / seconds,
            'scan_rate': len(scans) / seconds, 'cpu': cpu / wall, 'factor': seconds / wall}


def run(current: Session, seconds: float = SECONDS, update_min_d: float = 0.25,
        update_min_a: float = 0.2, extra: dict[str, str] | None = None
        ) -> tuple[list[Row], dict]:
    extra = extra or {}
    r = drive(current, seconds, update_min_d, update_min_a, extra)
    label = f'{seconds:g} s loop, update_min_d {update_min_d:g} / update_min_a {update_min_a:g}'
    label += ''.join(f', {k} {v}' for k, v in extra.items())
    rows = [
        Row('amcl_drive', f'{label}: RMS / max position error vs ground truth (first 10 % '
            f'of {r["updates"]} updates left out)',
            f'{r["rms"] * 100:.1f} / {r["max"] * 100:.1f} cm', '<= 5 cm',
            verdict(r['rms'] <= 0.05)),
        Row('amcl_drive', f'{label}: mean error along / across the heading; in x / y',
            f'{r["along"] * 100:+.1f} / {r["across"] * 100:+.1f} cm; '
            f'{r["dx"] * 100:+.1f} / {r["dy"] * 100:+.1f} cm'),
        Row('amcl_drive', f'{label}: scans answered with map -> odom, of {r["scans"]} '
            f'({r["scan_rate"]:.1f} Hz)', f'{r["handled"] * 100:.0f} %', '100 %',
            verdict(r['handled'] >= 0.99)),
        Row('amcl_drive', f'{label}: filter updates per second',
            f'{r["update_rate"]:.1f} Hz'),
        Row('amcl_drive', f'{label}: amcl CPU (one core), real-time factor reached',
            f'{r["cpu"] * 100:.0f} %, {r["factor"]:.2f}'),
    ]
    return rows, {'amcl_drive': r}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--seconds', type=float, default=SECONDS)
    parser.add_argument('--update-min-d', type=float, default=0.25)
    parser.add_argument('--update-min-a', type=float, default=0.2)
    parser.add_argument('--set', action='append', default=[], metavar='NAME=VALUE',
                        help="another of amcl's parameters (e.g. --set sigma_hit=0.1)")
    options = parser.parse_args()
    extra = dict(item.split('=', 1) for item in options.set)
    with session('amcl_drive') as current:
        rows, _ = run(current, options.seconds, options.update_min_d, options.update_min_a,
                      extra)
    for row in rows:
        print(f'{row.metric}: {row.value} {row.target} {row.verdict}')


if __name__ == '__main__':
    main()
