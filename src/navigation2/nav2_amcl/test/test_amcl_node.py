"""`ros2 run nav2_amcl amcl` over real DDS: map, initial pose and scans in; pose and TF out.

The probe plays map_server, the odometry (odom -> base_footprint on /tf) and the laser (in
base_footprint) in test_amcl_filter's synthetic room, with the robot standing still: each
request_nomotion_update makes the next scan a filter update.
"""

from __future__ import annotations

import math

import numpy as np
from geometry_msgs.msg import PoseWithCovarianceStamped, TransformStamped
from nav2_msgs.msg import ParticleCloud
from nav_msgs.msg import OccupancyGrid
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy, qos_profile_sensor_data
from sensor_msgs.msg import LaserScan
from std_srvs.srv import Empty
from test_amcl_filter import RANGE_MAX, RESOLUTION, SCAN_BEAMS, _grid, _scan
from tf2_msgs.msg import TFMessage

from ws_testing import TestNode

LATCHED = QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
                     reliability=ReliabilityPolicy.RELIABLE)
TRUTH = np.array([3.0, 3.5, 0.3])  # the robot in the map
ODOM = np.array([0.5, -0.2, 0.1])  # the robot in odom


def _map_msg(probe: TestNode) -> OccupancyGrid:
    amcl_map = _grid()
    grid = OccupancyGrid()
    grid.header.frame_id = 'map'
    grid.header.stamp = probe.node.get_clock().now().to_msg()
    grid.info.resolution = RESOLUTION
    grid.info.height, grid.info.width = amcl_map.states.shape
    grid.data = np.where(amcl_map.states == 1, 100, 0).astype(np.int8).ravel().tolist()
    return grid


def _odom_tf(stamp) -> TFMessage:
    t = TransformStamped()
    t.header.frame_id, t.child_frame_id = 'odom', 'base_footprint'
    t.header.stamp = stamp
    t.transform.translation.x, t.transform.translation.y = float(ODOM[0]), float(ODOM[1])
    t.transform.rotation.z, t.transform.rotation.w = math.sin(ODOM[2] / 2), math.cos(ODOM[2] / 2)
    identity = TransformStamped()
    identity.header.frame_id, identity.child_frame_id = 'base_footprint', 'base_scan'
    identity.header.stamp = stamp
    identity.transform.rotation.w = 1.0
    return TFMessage(transforms=[t, identity])


def _scan_msg(stamp, rng: np.random.Generator) -> LaserScan:
    scan = LaserScan()
    scan.header.frame_id, scan.header.stamp = 'base_scan', stamp
    scan.angle_min, scan.angle_increment = -math.pi, 2 * math.pi / SCAN_BEAMS
    scan.angle_max = scan.angle_min + scan.angle_increment * (SCAN_BEAMS - 1)
    scan.range_min, scan.range_max = 0.1, RANGE_MAX
    scan.ranges = [float(r) for r in _scan(TRUTH, rng)]
    return scan


def _yaw(q) -> float:
    return math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))


def test_amcl_localises_and_publishes_pose_cloud_and_map_to_odom(launch, ros_env):
    amcl = launch('nav2_amcl', 'amcl', '--ros-args', '-p', 'autostart_node:=true',
                  '-p', 'alpha1:=0.05', '-p', 'alpha2:=0.05', '-p', 'alpha3:=0.05',
                  '-p', 'alpha4:=0.05', '-p', 'max_particles:=1000', '-p', 'bogus:=1')
    amcl.wait_for_output(r"Ignoring unknown parameter 'bogus'", timeout=20.0)
    amcl.wait_for_output(r'Activating', timeout=20.0)
    probe = TestNode(int(ros_env['ROS_DOMAIN_ID']))
    rng = np.random.default_rng(3)
    try:
        node = probe.node
        map_pub = node.create_publisher(OccupancyGrid, 'map', LATCHED)
        tf_pub = node.create_publisher(TFMessage, '/tf', 100)
        scan_pub = node.create_publisher(LaserScan, 'scan', qos_profile_sensor_data)
        pose_pub = node.create_publisher(PoseWithCovarianceStamped, 'initialpose', 10)
        poses = probe.collect(PoseWithCovarianceStamped, 'amcl_pose', LATCHED)
        clouds = probe.collect(ParticleCloud, 'particle_cloud', qos_profile_sensor_data)
        tfs = probe.collect(TFMessage, '/tf', 100)
        map_pub.publish(_map_msg(probe))
        amcl.wait_for_output(r'Received a 200 X 140 map @ 0.050 m/pix', timeout=20.0)
        initial = PoseWithCovarianceStamped()
        initial.header.frame_id = 'map'
        initial.pose.pose.position.x, initial.pose.pose.position.y = 3.2, 3.35
        initial.pose.pose.orientation.z = math.sin(0.2)
        initial.pose.pose.orientation.w = math.cos(0.2)
        covariance = [0.0] * 36
        covariance[0] = covariance[7] = 0.04
        covariance[35] = 0.02
        initial.pose.covariance = covariance
        probe.spin_until(lambda: pose_pub.get_subscription_count() > 0, 10.0,
                         'amcl on /initialpose')
        pose_pub.publish(initial)
        amcl.wait_for_output(r'initialPoseReceived: setting pose \([0-9.]+\): 3.200 3.350 0.400',
                             timeout=10.0)
        for _ in range(12):  # a still robot: one forced filter update per scan
            stamp = node.get_clock().now().to_msg()
            tf_pub.publish(_odom_tf(stamp))
            probe.spin_for(0.05)
            count = len(poses)
            probe.call(Empty, 'request_nomotion_update', Empty.Request())
            scan_pub.publish(_scan_msg(stamp, rng))
            probe.spin_until(lambda count=count: len(poses) > count, 10.0, 'a new amcl_pose')
        last = poses[-1]
        assert last.header.frame_id == 'map'
        p = last.pose.pose
        assert math.hypot(p.position.x - TRUTH[0], p.position.y - TRUTH[1]) < 0.1
        assert abs(_yaw(p.orientation) - TRUTH[2]) < 0.05
        assert 0 < last.pose.covariance[0] < 0.04 and last.pose.covariance[35] > 0
        assert clouds and 0 < len(clouds[-1].particles) <= 1000
        map_to_odom = [t for m in tfs for t in m.transforms if t.child_frame_id == 'odom']
        assert map_to_odom and map_to_odom[-1].header.frame_id == 'map'
        t = map_to_odom[-1].transform
        tyaw = _yaw(t.rotation)
        # map -> odom composed with odom -> base gives the robot in the map
        bx = t.translation.x + ODOM[0] * math.cos(tyaw) - ODOM[1] * math.sin(tyaw)
        by = t.translation.y + ODOM[0] * math.sin(tyaw) + ODOM[1] * math.cos(tyaw)
        assert math.hypot(bx - TRUTH[0], by - TRUTH[1]) < 0.1
        assert abs(tyaw + ODOM[2] - TRUTH[2]) < 0.05
        probe.call(Empty, 'reinitialize_global_localization', Empty.Request())
        amcl.wait_for_output(r'Global initialisation done!', timeout=10.0)
    finally:
        probe.close()


def test_a_wrong_model_name_fails_configure_in_one_line(launch):
    amcl = launch('nav2_amcl', 'amcl', '--ros-args', '-p', 'autostart_node:=true',
                  '-p', 'robot_model_type:=nav2_amcl::Differential')
    amcl.wait_for_output(r"\[ERROR\] \[[0-9.]+\] \[amcl\]: robot_model_type: "
                         r"'nav2_amcl::Differential' is not one of", timeout=20.0)
    amcl.wait_for_output(r'Auto-starting node amcl failed to configure!', timeout=10.0)
    assert 'Traceback' not in amcl.output
