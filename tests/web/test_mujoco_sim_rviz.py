"""`ros2 launch diffbot_bringup diffbot_sim.launch.py` as the simulation page has the learner
run it: the room world, robot_state_publisher on sim time and the RViz page with the package's
diffbot.rviz, which draws the robot, its frames, the scan, the odometry and the camera image
(the red box ahead is red in the image panel). Screenshot: artifacts/rqt/rviz_diffbot.png."""

from __future__ import annotations

from pathlib import Path

import pytest

from rqt_browser import chromium_missing, screenshot
from support import RosProcess, TestNode
from ws_testing.browser import rviz_page

DIFFBOT_LINKS = {'base_link', 'caster_link', 'left_wheel_link', 'right_wheel_link',
                 'lidar_link', 'camera_link'}


def test_bringup_shows_the_robot_scan_and_camera_in_rviz(tmp_path: Path, domain: int,
                                                          ros_env) -> None:
    reason = chromium_missing()
    if reason:
        pytest.skip(reason)
    from ament_index_python.packages import get_package_share_directory
    from PIL import Image

    config = Path(get_package_share_directory('diffbot_bringup')) / 'rviz' / 'diffbot.rviz'
    bringup = RosProcess(['ros2', 'launch', 'diffbot_bringup', 'diffbot_sim.launch.py',
                          'rviz:=false'], ros_env, tmp_path / 'launch.log')
    probe = TestNode(domain)
    try:
        bringup.wait_for_output(r'\[mujoco_sim-1\] .*\[mujoco_sim\]: Loaded world .*room\.xml'
                                r"' \(\d+ bodies\) with robot 'diffbot'", timeout=30)
        bringup.wait_for_output(r'\[robot_state_publisher-2\] .*Robot initialized', timeout=20)
        with rviz_page(ros_env, probe, config, tmp_path) as (_server, page):
            page.wait_for_function(
                '''() => window.rviz && window.rviz.ready
                    && ['RobotModel', 'LaserScan', 'Odometry', 'Camera'].every(
                        (name) => window.rviz.status[name] === 'OK')
                    && window.rviz.images.Camera && window.rviz.images.Camera.drawn > 0
                    && window.rviz.links.length >= 6''', timeout=40000)
            page.wait_for_timeout(300)  # a few frames with everything drawn
            state = page.evaluate('window.rviz')
            box = page.locator('canvas.rviz-image[data-name="Camera"]').bounding_box()
            shot = screenshot(page, 'rviz_diffbot')
    finally:
        probe.close()
        assert bringup.stop() == 0, bringup.output
    assert set(state['links']) >= DIFFBOT_LINKS, state['links']
    assert state['fixedFrame'] == 'odom'
    camera = state['images']['Camera']
    assert (camera['width'], camera['height'], camera['encoding']) == (320, 240, 'rgb8')
    # The room's red box stands 1.5 m ahead of the robot: red in the middle of the image.
    shown = Image.open(shot).convert('RGB')
    r, g, b = shown.getpixel((int(box['x'] + box['width'] / 2),
                              int(box['y'] + box['height'] / 2)))
    assert r > 150 and g < 80 and b < 80, (r, g, b)
