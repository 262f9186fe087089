"""The dummy-robot demo page as written: `ros2 launch dummy_robot_bringup
dummy_robot_bringup_launch.py` prints what the page shows, its nodes publish the map, the
scan and the joint states, and the RViz page (with the package's dummy_robot.rviz: Map,
LaserScan, RobotModel, TF in frame world) draws the map, the laser and the moving arm in
headless Chromium. Screenshot: artifacts/rqt/rviz_dummy_robot.png. The package's XML and YAML
launch files start the same robot, the URDF read with `$(file-content ...)`."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from nav_msgs.msg import OccupancyGrid
from rclpy.qos import DurabilityPolicy, QoSProfile
from sensor_msgs.msg import JointState, LaserScan
from std_msgs.msg import String

from rqt_browser import chromium_missing, close_to, launch_browser, screenshot, start_rqt
from support import Background, RosProcess, TestNode, wait_until

RRBOT_LINKS = {'single_rrbot_link1', 'single_rrbot_link2', 'single_rrbot_link3',
               'single_rrbot_hokuyo_link', 'single_rrbot_camera_link'}
UNKNOWN_ON_BACKGROUND = (93, 110, 108)  # rviz's unknown-cell colour at alpha 0.7 on 48 grey


@pytest.mark.parametrize('launch_file', ['dummy_robot_bringup_launch.xml',
                                         'dummy_robot_bringup_launch.yaml'])
def test_dummy_robot_bringup_front_ends(launch_file: str, tmp_path: Path, domain: int,
                                        ros_env) -> None:
    from ament_index_python.packages import get_package_share_directory
    urdf = (Path(get_package_share_directory('dummy_robot_bringup')) / 'launch' /
            'single_rrbot.urdf').read_text()
    bringup = RosProcess(['ros2', 'launch', 'dummy_robot_bringup', launch_file], ros_env,
                         tmp_path / 'launch.log')
    probe = TestNode(domain)
    try:
        bringup.wait_for_output(r'\[robot_state_publisher-2\] .*\[robot_state_publisher\]: '
                                r'Robot initialized', timeout=20)
        bringup.wait_for_output(r'\[dummy_laser-4\] .*\[dummy_laser\]: scan size:\t1081$')
        descriptions = probe.collect(String, '/robot_description', QoSProfile(
            depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL))
        maps = probe.collect(OccupancyGrid, '/map', QoSProfile(
            depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL))
        joints = probe.collect(JointState, '/joint_states')
        probe.spin_until(lambda: descriptions and maps and joints, 15,
                         'robot description, map and joint states')
    finally:
        probe.close()
        bringup.stop()
    # The parameter is the file's text, unchanged (not read as YAML, not stripped).
    assert descriptions[-1].data == urdf
    assert list(joints[-1].name) == ['single_rrbot_joint1', 'single_rrbot_joint2']


def test_dummy_robot_bringup_in_rviz(tmp_path: Path, domain: int, ros_env) -> None:
    reason = chromium_missing()
    if reason:
        pytest.skip(reason)
    from ament_index_python.packages import get_package_share_directory
    from PIL import Image
    from playwright.sync_api import sync_playwright

    config = Path(get_package_share_directory('dummy_robot_bringup')) / 'config' / \
        'dummy_robot.rviz'
    server, _ = start_rqt(ros_env, tmp_path / 'state')
    bringup = RosProcess(['ros2', 'launch', 'dummy_robot_bringup',
                          'dummy_robot_bringup_launch.py'], server.env, tmp_path / 'launch.log')
    probe = TestNode(domain)
    try:
        bringup.wait_for_output(r'\[dummy_laser-4\] \[INFO\] \[[\d.]+\] \[dummy_laser\]: '
                                r'angle inc:\t0\.004363$', timeout=20)
        bringup.wait_for_output(r'\[dummy_laser\]: scan size:\t1081$')
        bringup.wait_for_output(r'\[dummy_laser\]: scan time increment: \t0\.000000$')
        bringup.wait_for_output(r'\[robot_state_publisher-2\] .*\[robot_state_publisher\]: '
                                r'Robot initialized', timeout=20)
        maps = probe.collect(OccupancyGrid, '/map', QoSProfile(
            depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL))
        scans = probe.collect(LaserScan, '/scan')
        joints = probe.collect(JointState, '/joint_states')
        probe.spin_until(lambda: maps and scans and joints, 15, 'map, scan and joint states')
        grid, scan = maps[-1], scans[-1]
        assert (grid.header.frame_id, grid.info.width, grid.info.height) == ('world', 100, 100)
        assert grid.info.origin.position.x == pytest.approx(-5.0)
        assert sorted(set(grid.data)) == [-1, 0, 100]
        assert (scan.header.frame_id, len(scan.ranges)) == ('single_rrbot_hokuyo_link', 1081)
        assert scan.angle_min == pytest.approx(-3 * math.pi / 4, abs=1e-6)
        assert list(joints[-1].name) == ['single_rrbot_joint1', 'single_rrbot_joint2']

        with sync_playwright() as playwright, Background(probe):
            browser = launch_browser(playwright)
            try:
                page = browser.new_page(viewport={'width': 1280, 'height': 900})
                page.goto(server.page_url('/rviz', config=str(config)))
                page.wait_for_function(
                    '() => window.rviz && window.rviz.ready && window.rviz.maps.Map'
                    ' && window.rviz.maps.Map.drawn > 0 && window.rviz.status.Map === "OK"'
                    ' && window.rviz.status.LaserScan === "OK"'
                    ' && window.rviz.status.RobotModel === "OK"'
                    ' && window.rviz.links.length >= 6', timeout=40000)
                tip = page.evaluate('window.rviz.frames.single_rrbot_hokuyo_link.translation')
                wait_until(lambda: page.evaluate(
                    'window.rviz.frames.single_rrbot_hokuyo_link.translation') != tip, 5,
                    'the arm to move')
                state = page.evaluate('window.rviz')
                # A map cell far from the robot, between grid lines, where it shows.
                x, y = page.evaluate('window.rviz.project(-3.45, -3.45, 0)')
                shot = screenshot(page, 'rviz_dummy_robot')
            finally:
                browser.close()
    finally:
        probe.close()
        bringup.stop()
        server.stop()
    assert set(state['links']) >= RRBOT_LINKS, state['links']
    assert state['maps']['Map'] | {'drawn': 0, 'seq': 0, 'received': 0} == {
        'received': 0, 'drawn': 0, 'width': 100, 'height': 100, 'resolution': pytest.approx(0.1),
        'frame': 'world', 'seq': 0, 'scheme': 'map'}
    image = Image.open(shot).convert('RGB')
    pixel = image.getpixel((int(x), int(y)))
    assert close_to(pixel, UNKNOWN_ON_BACKGROUND), pixel
