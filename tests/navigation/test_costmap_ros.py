"""The global costmap node inside planner_server over real DDS: a scan marks an obstacle seen
through get_costmap, the robot's footprint is published, clear_entirely answers.

Same world as test_planner_server (its map and params); the servers start themselves
(`autostart_node`) instead of through lifecycle_manager.
"""

from __future__ import annotations

import math

import numpy as np
from geometry_msgs.msg import PolygonStamped
from nav2_msgs.srv import ClearEntireCostmap, GetCostmap
from rclpy.qos import qos_profile_sensor_data
from sensor_msgs.msg import LaserScan
from test_planner_server import HEIGHT, ROBOT, WIDTH, write_map, write_params

from support import TestNode


def _scan(probe: TestNode) -> LaserScan:
    """An arc 1 m in front of the robot (base_footprint faces +x)."""
    scan = LaserScan()
    scan.header.frame_id = 'base_footprint'
    scan.header.stamp = probe.node.get_clock().now().to_msg()
    scan.angle_min, scan.angle_increment = -0.5, 0.01
    scan.angle_max = scan.angle_min + 100 * scan.angle_increment
    scan.range_min, scan.range_max = 0.1, 10.0
    scan.ranges = [1.0] * 101
    return scan


def _costs(probe: TestNode) -> np.ndarray:
    response = probe.call(GetCostmap, '/global_costmap/get_costmap', GetCostmap.Request())
    meta = response.map.metadata
    return np.frombuffer(bytes(response.map.data), dtype=np.uint8).reshape(meta.size_y,
                                                                             meta.size_x)


def test_scan_marks_the_costmap_and_footprint_is_published(launch, ros_env, tmp_path):
    launch('nav2_map_server', 'map_server', '--ros-args', '-p',
           f'yaml_filename:={write_map(tmp_path)}', '-p', 'autostart_node:=true')
    launch('tf2_ros', 'static_transform_publisher', '--x', str(ROBOT[0]), '--y', str(ROBOT[1]),
           '--frame-id', 'map', '--child-frame-id', 'base_footprint')
    planner = launch('nav2_planner', 'planner_server', '--ros-args', '--params-file',
                     str(write_params(tmp_path, 'nav2_navfn_planner/NavfnPlanner')),
                     '-p', 'autostart_node:=true')
    planner.wait_for_output(r'\[planner_server\]: Activating', timeout=30.0)
    planner.wait_for_output(r'StaticLayer: Resizing costmap to 120 X 80 at 0\.050000 m/pix',
                            timeout=20.0)
    probe = TestNode(int(ros_env['ROS_DOMAIN_ID']))
    try:
        footprints = probe.collect(PolygonStamped, '/global_costmap/published_footprint')
        scans = probe.node.create_publisher(LaserScan, '/scan', qos_profile_sensor_data)
        obstacle = (20, 40)  # row, column of (2.0, 1.0): 1 m ahead of the robot
        near = np.s_[19:22, 39:42]
        for _ in range(40):  # until an update (2 Hz) has layered the map in: ~10 s at most
            costs = _costs(probe)
            if costs[obstacle] != 255:
                break
            probe.spin_for(0.25)
        assert costs.shape == (HEIGHT, WIDTH)
        assert costs[obstacle] < 253  # free on the map, 0.4 m from the wall: inflated only
        for _ in range(40):  # 2 Hz updates: bounded to ~10 s
            scans.publish(_scan(probe))
            probe.spin_for(0.25)
            costs = _costs(probe)
            if costs[near].max() == 254:
                break
        assert costs[near].max() == 254  # the beam ends at a cell's edge: either side of it
        assert costs[20, 30] < 253  # the beams' free space in between
        probe.spin_until(lambda: len(footprints) > 0, 5.0, 'the published footprint')
        points = footprints[-1].polygon.points
        assert footprints[-1].header.frame_id == 'map' and len(points) == 16
        # robot_radius 0.15 plus footprint_padding 0.01 on each axis
        assert all(0.15 < math.hypot(p.x - ROBOT[0], p.y - ROBOT[1]) < 0.175 for p in points)
        probe.call(ClearEntireCostmap, '/global_costmap/clear_entirely_global_costmap',
                   ClearEntireCostmap.Request())
        planner.wait_for_output('Received request to clear entirely the global_costmap')
    finally:
        probe.close()
    assert 'Traceback' not in planner.output
