"""nav2_bringup's tb3_simulation_launch.py on the MuJoCo warehouse, as a user runs it:
`ros2 launch nav2_bringup tb3_simulation_launch.py headless:=True use_rviz:=False`.

Every built lifecycle node is active within a bounded time, each node Nav2 names that this
workspace does not build is named once ("... is not built here; left out"), BasicNavigator
gets an amcl_pose after setInitialPose and a path from getPath; once controller_server and
bt_navigator exist, goToPose drives the robot to a goal 7 m away and the simulator's ground
truth ends within TRUTH_BOUND of it. Ctrl-C of the launch ends every process cleanly.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

from geometry_msgs.msg import PoseWithCovarianceStamped
from nav_msgs.msg import Odometry
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy

from support import TestNode

GOAL = (7.0, 0.5)  # m, in the map (= world) frame; 7.0 m from the start, round a pillar
# The robot stops once amcl puts it within xy_goal_tolerance (0.25 m) of the goal, and there
# amcl's estimate is 0.3-0.46 m off the truth (x too far, y too low): the truth ended 0.15,
# 0.27, 0.38, 0.42, 0.43, 0.50, 0.52, 0.64, 0.64 m from the goal in nine runs (composed or
# not, goal tolerance 0.25 or 0.12). Until amcl does better there, the bound is 1.0 m; a
# robot that did not drive ends 7 m off.
TRUTH_BOUND = 1.0  # m
NAV_CLIENT = """\
import sys
import time

import rclpy
from geometry_msgs.msg import PoseStamped
from nav2_simple_commander.robot_navigator import BasicNavigator


def pose(navigator, x, y):
    msg = PoseStamped()
    msg.header.frame_id = 'map'
    msg.header.stamp = navigator.get_clock().now().to_msg()
    msg.pose.position.x, msg.pose.position.y = x, y
    msg.pose.orientation.w = 1.0
    return msg


rclpy.init()
navigator = BasicNavigator()
start = pose(navigator, 0.0, 0.0)
navigator.setInitialPose(start)
navigator.waitUntilNav2Active()
goal = pose(navigator, {x}, {y})
path = navigator.getPath(start, goal)
print(f'path of {{len(path.poses)}} poses', flush=True)
if '--drive' in sys.argv:
    navigator.goToPose(goal)
    while not navigator.isTaskComplete():
        time.sleep(0.1)
    print(f'result {{navigator.getResult().name}}', flush=True)
navigator.destroy_node()
rclpy.shutdown()
"""


def _built(package: str, executable: str) -> bool:
    from nav2_bringup.nodes import Server, is_built
    return is_built(Server(executable, package, executable, ''))


def test_tb3_simulation_comes_up_plans_and_drives(launch, ros_env, tmp_path: Path) -> None:
    from nav2_bringup.nodes import LOCALIZATION, NAVIGATION, is_built
    bringup = launch(argv=['ros2', 'launch', 'nav2_bringup', 'tb3_simulation_launch.py',
                           'headless:=True', 'use_rviz:=False'])
    bringup.wait_for_output(r'\[lifecycle_manager_localization\]: .*Managed nodes are active',
                            timeout=90)
    bringup.wait_for_output(r'\[lifecycle_manager_navigation\]: .*Managed nodes are active',
                            timeout=60)
    out = bringup.output
    for server in NAVIGATION + LOCALIZATION:
        left_out = out.count(f'{server.name} is not built here; left out')
        if is_built(server):
            assert left_out == 0, server.name
            assert f'[{server.name}]: Activating' in out, server.name
        else:
            assert left_out == 1, (server.name, out)
    drive = _built('nav2_controller', 'controller_server') and \
        _built('nav2_bt_navigator', 'bt_navigator')
    script = tmp_path / 'nav_client.py'
    script.write_text(NAV_CLIENT.format(x=GOAL[0], y=GOAL[1]))
    probe = TestNode(int(ros_env['ROS_DOMAIN_ID']))
    try:
        truths = probe.collect(Odometry, '/ground_truth/odom', 50)
        estimates = probe.collect(PoseWithCovarianceStamped, '/amcl_pose', QoSProfile(
            depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL,
            reliability=ReliabilityPolicy.RELIABLE))
        client = launch(argv=[sys.executable, str(script)] + (['--drive'] if drive else []))
        client.wait_for_output('Nav2 is ready for use!', timeout=60)
        poses = int(client.wait_for_output(r'path of (\d+) poses', timeout=30).group(1))
        assert poses > 140  # 7 m at 0.05 m per cell, round the pillar
        if not drive:
            return
        client.wait_for_output(r'result (\w+)', timeout=150)
        assert 'result SUCCEEDED' in client.output, client.output
        probe.spin_until(lambda: truths, 10, 'the ground truth')
        end = truths[-1].pose.pose.position
        error = math.hypot(end.x - GOAL[0], end.y - GOAL[1])
        probe.spin_for(0.5)
        amcl = estimates[-1].pose.pose.position if estimates else end
        amcl_error = math.hypot(amcl.x - end.x, amcl.y - end.y)
        print(f'goal {GOAL}: ended at ({end.x:.3f}, {end.y:.3f}), {error:.3f} m off; amcl '
              f'said ({amcl.x:.3f}, {amcl.y:.3f}), {amcl_error:.3f} m from the truth')
        assert error < TRUTH_BOUND, (end.x, end.y, amcl.x, amcl.y)
    finally:
        probe.close()
    assert bringup.stop(timeout=10) == 0, bringup.output[-3000:]
    tail = bringup.output
    assert 'process has finished cleanly' in tail and 'process has died' not in tail, tail
