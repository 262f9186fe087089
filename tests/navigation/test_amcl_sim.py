"""AMCL against the MuJoCo simulator: the warehouse world, map_server with the map
world_to_map made from it, amcl and a lifecycle_manager, all on sim time. After an
/initialpose near (not at) the truth and a few seconds of driving, amcl_pose is within
0.10 m and 0.10 rad of /ground_truth/odom at the same stamp.

The map's frame is the world's: world_to_map writes the map's origin in world coordinates,
so a map point is the world point of the same coordinates (test_warehouse_world checks the
lidar's rays against the map at the simulator's true pose)."""

from __future__ import annotations

import math
from pathlib import Path

from geometry_msgs.msg import PoseWithCovarianceStamped, Twist
from nav_msgs.msg import Odometry
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

from support import TestNode

LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                     reliability=ReliabilityPolicy.RELIABLE)
# Nav2's amcl section, with the simulator's odometry in mind: its wheel odometry drifts
# little, so alphas of 0.05 (Nav2's 0.2 keeps the cloud ~0.25 m wide) and updates every
# 0.1 m / 0.1 rad so that a few seconds of driving give several filter updates.
AMCL_PARAMS = """\
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
    max_beams: 60
    max_particles: 1000
    min_particles: 200
    update_min_d: 0.1
    update_min_a: 0.1
    transform_tolerance: 1.0
map_server:
  ros__parameters:
    use_sim_time: true
    yaml_filename: {map}
lifecycle_manager:
  ros__parameters:
    use_sim_time: true
    autostart: true
    node_names: ['map_server', 'amcl']
"""
START_ERROR = (0.2, -0.15, 0.1)  # the initial pose's offset from the truth: x, y (m), yaw
DRIVE = (0.3, 0.25)  # m/s, rad/s: an arc that stays clear of the warehouse's shelves


def _yaw(q) -> float:
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


def _seconds(stamp) -> float:
    return stamp.sec + stamp.nanosec * 1e-9


def _angle(a: float) -> float:
    return math.atan2(math.sin(a), math.cos(a))


def test_amcl_tracks_the_simulated_robot(launch, ros_env, tmp_path: Path) -> None:
    from ament_index_python.packages import get_package_share_directory
    world_map = Path(get_package_share_directory('mujoco_sim')) / 'maps' / 'warehouse.yaml'
    params = tmp_path / 'nav2_params.yaml'
    params.write_text(AMCL_PARAMS.format(map=world_map))
    launch(argv=['ros2', 'launch', 'diffbot_bringup', 'diffbot_sim.launch.py',
                 'world:=warehouse.xml', 'rviz:=false'])
    launch('nav2_map_server', 'map_server', '--ros-args', '--params-file', str(params))
    amcl = launch('nav2_amcl', 'amcl', '--ros-args', '--params-file', str(params))
    manager = launch('nav2_lifecycle_manager', 'lifecycle_manager', '--ros-args',
                     '--params-file', str(params))
    manager.wait_for_output('Managed nodes are active', timeout=40)
    amcl.wait_for_output(r'Received a \d+ X \d+ map', timeout=10)
    probe = TestNode(int(ros_env['ROS_DOMAIN_ID']))
    try:
        node = probe.node
        truths = probe.collect(Odometry, '/ground_truth/odom', 200)
        poses = probe.collect(PoseWithCovarianceStamped, '/amcl_pose', LATCHED)
        initial_pub = node.create_publisher(PoseWithCovarianceStamped, '/initialpose', 10)
        cmd_pub = node.create_publisher(Twist, '/cmd_vel', 10)
        probe.spin_until(lambda: truths, 30, 'the ground truth')
        start = truths[-1].pose.pose
        x0, y0, yaw0 = start.position.x, start.position.y, _yaw(start.orientation)
        initial = PoseWithCovarianceStamped()
        initial.header.frame_id = 'map'
        initial.header.stamp = truths[-1].header.stamp
        p = initial.pose.pose
        p.position.x, p.position.y = x0 + START_ERROR[0], y0 + START_ERROR[1]
        p.orientation.z = math.sin((yaw0 + START_ERROR[2]) / 2)
        p.orientation.w = math.cos((yaw0 + START_ERROR[2]) / 2)
        cov = [0.0] * 36
        cov[0] = cov[7] = 0.25 ** 2
        cov[35] = 0.15 ** 2
        initial.pose.covariance = cov
        probe.spin_until(lambda: initial_pub.get_subscription_count() > 0, 10,
                         'amcl on /initialpose')
        initial_pub.publish(initial)
        amcl.wait_for_output('initialPoseReceived', timeout=10)
        twist = Twist()
        twist.linear.x, twist.angular.z = DRIVE
        cmd_timer = node.create_timer(0.1, lambda: cmd_pub.publish(twist))
        t0 = _seconds(truths[-1].header.stamp)
        # Five seconds of sim time driving, then stop and take the last estimate.
        probe.spin_until(lambda: _seconds(truths[-1].header.stamp) > t0 + 5.0, 30,
                         'five seconds of driving')
        node.destroy_timer(cmd_timer)
        cmd_pub.publish(Twist())
        probe.spin_until(lambda: poses and _seconds(poses[-1].header.stamp) > t0 + 4.0, 10,
                         'an amcl_pose from the last second of driving')
        estimate = poses[-1]
        stamp = _seconds(estimate.header.stamp)
        truth = min(truths, key=lambda m: abs(_seconds(m.header.stamp) - stamp))
        assert abs(_seconds(truth.header.stamp) - stamp) < 0.03
        e, t = estimate.pose.pose, truth.pose.pose
        error = math.hypot(e.position.x - t.position.x, e.position.y - t.position.y)
        yaw_error = abs(_angle(_yaw(e.orientation) - _yaw(t.orientation)))
        travelled = math.hypot(t.position.x - x0, t.position.y - y0)
        print(f'amcl_pose {len(poses)} updates; last error {error:.3f} m '
              f'{yaw_error:.3f} rad after {travelled:.2f} m')
        assert travelled > 0.8
        assert error < 0.10, (error, e.position, t.position)
        assert yaw_error < 0.10, yaw_error
    finally:
        probe.close()
