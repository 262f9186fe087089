"""The RViz page in headless Chromium with "Using URDF with robot_state_publisher (Python)":
the r2d2 demo (robot_state_publisher + state_publisher) and the page's r2d2.rviz. The model is
drawn where tf2 puts it: `axis` on its 2 m circle around `odom`, every link placed, the
displays' status OK, and the canvas shows the robot (its blue body's pixels).
Screenshot: artifacts/rqt/rviz_r2d2.png.
"""
from __future__ import annotations

import math
from pathlib import Path

import pytest

from ws_testing import RosProcess, leased_domain, ros_environment
from ws_testing.browser import chromium_missing, launch_browser, screenshot, start_rqt

LINKS = {'axis', 'body', 'head', 'rod', 'box', 'leg1', 'leg2'}


def test_rviz_page_draws_r2d2_where_tf2_puts_it(tmp_path: Path) -> None:
    reason = chromium_missing()
    if reason:
        pytest.skip(reason)
    from ament_index_python.packages import get_package_share_directory
    from PIL import Image
    from playwright.sync_api import sync_playwright

    config = Path(get_package_share_directory('urdf_tutorial_r2d2')) / 'r2d2.rviz'
    with leased_domain() as domain:
        env = ros_environment(domain)
        server, _ = start_rqt(env, tmp_path / 'state')
        demo = RosProcess(['ros2', 'launch', 'urdf_tutorial_r2d2', 'demo.launch.py'],
                          server.env, tmp_path / 'demo.log')
        try:
            with sync_playwright() as playwright:
                browser = launch_browser(playwright)
                try:
                    page = browser.new_page(viewport={'width': 1280, 'height': 900})
                    page.goto(server.page_url('/rviz', config=str(config)))
                    page.wait_for_function(
                        '() => window.rviz && window.rviz.ready && window.rviz.links.length >= 7'
                        ' && window.rviz.status.RobotModel === "OK" && window.rviz.frames.box'
                        ' && !window.rviz.frames.box.error', timeout=40000)
                    page.wait_for_timeout(500)
                    state = page.evaluate('window.rviz')
                    shot = screenshot(page, 'rviz_r2d2')
                    canvas = page.locator('#rviz-view canvas').bounding_box()
                finally:
                    browser.close()
        finally:
            demo.stop()
            server.stop()
    assert state['fixedFrame'] == 'odom'
    assert set(state['links']) >= LINKS, state['links']
    assert state['status']['TF'] == 'OK' and state['status']['Grid'] == 'OK', state['status']
    axis = state['frames']['axis']['translation']
    assert math.hypot(axis[0], axis[1]) == pytest.approx(2.0, abs=0.05), axis
    # The fixed legs hang from axis as the URDF says (latched on /tf_static).
    leg1 = state['frames']['leg1']['translation']
    assert math.dist(leg1, axis) == pytest.approx(0.3, abs=0.01)  # <origin xyz="0 0.3 0"/>
    # The body is r2d2.urdf.xml's blue: count those pixels (the grid and background are grey).
    image = Image.open(shot).convert('RGB')
    left, top = int(canvas['x']), int(canvas['y'])
    raw = image.crop((left, top, left + int(canvas['width']),
                      top + int(canvas['height']))).tobytes()
    blue = sum(1 for i in range(0, len(raw), 3)
               if raw[i + 2] > raw[i] + 15 and raw[i + 2] > raw[i + 1] + 15)
    assert blue > 500, f'only {blue} blue pixels: the robot is not drawn'


def test_rviz_page_shows_the_turtle_frames_moving(tmp_path: Path) -> None:
    """The tf2 introduction's rviz step: `rviz2 -d .../turtle_tf2_py/rviz/turtle_rviz.rviz`
    with the turtle demo: turtle1 and turtle2 under world, turtle2 moving as it follows."""
    reason = chromium_missing()
    if reason:
        pytest.skip(reason)
    from ament_index_python.packages import get_package_share_directory
    from playwright.sync_api import sync_playwright

    config = Path(get_package_share_directory('turtle_tf2_py')) / 'rviz' / 'turtle_rviz.rviz'
    with leased_domain() as domain:
        env = ros_environment(domain)
        server, _ = start_rqt(env, tmp_path / 'state')
        demo = RosProcess(['ros2', 'launch', 'turtle_tf2_py', 'turtle_tf2_demo.launch.py'],
                          server.env, tmp_path / 'demo.log')
        try:
            demo.wait_for_output(r'Successfully spawned turtle2', timeout=40)
            with sync_playwright() as playwright:
                browser = launch_browser(playwright)
                try:
                    page = browser.new_page(viewport={'width': 1280, 'height': 900})
                    page.goto(server.page_url('/rviz', config=str(config)))
                    page.wait_for_function(
                        '() => window.rviz && window.rviz.ready && window.rviz.frames.turtle2'
                        ' && !window.rviz.frames.turtle2.error', timeout=40000)
                    # It drives: away from where the demo spawns it (4, 2), towards turtle1
                    # (asserted below).
                    page.wait_for_function(
                        '() => Math.hypot(window.rviz.frames.turtle2.translation[0] - 4,'
                        ' window.rviz.frames.turtle2.translation[1] - 2) > 0.5', timeout=10000)
                    state = page.evaluate('window.rviz')
                    projected = page.evaluate('[window.rviz.project(0, 0, 0), window.rviz.project('
                                              '...window.rviz.frames.turtle1.translation)]')
                    screenshot(page, 'rviz_turtles')
                    # The Fixed Frame box: the next answer is in turtle1 (the request in flight
                    # for world is cancelled), where turtle1 is the origin and world is not.
                    page.fill('#rviz-fixed-frame', 'turtle1')
                    page.dispatch_event('#rviz-fixed-frame', 'change')
                    page.wait_for_function(
                        '() => window.rviz.frames.world && !window.rviz.frames.world.error'
                        ' && window.rviz.frames.turtle1.translation.every((v) => v === 0)',
                        timeout=10000)
                    in_turtle1 = page.evaluate('window.rviz.frames')
                finally:
                    browser.close()
        finally:
            demo.stop()
            server.stop()
    assert state['fixedFrame'] == 'world'
    assert state['status']['TF'] == 'OK', state['status']
    turtle1 = state['frames']['turtle1']['translation']
    assert turtle1[:2] == pytest.approx([5.544445, 5.544445], abs=0.01)
    # Sampling it twice instead could find it arrived already, on a machine slow to load the page.
    assert math.dist([4.0, 2.0], state['frames']['turtle2']['translation'][:2]) > 0.5
    assert {p['fixed_frame'] for p in in_turtle1.values()} == {'turtle1'}
    assert in_turtle1['world']['translation'][:2] == pytest.approx([-5.544445, -5.544445],
                                                                   abs=0.01)
    # The file's TopDownOrtho view (48.6 px/m around the origin): turtle1 drawn where rviz2
    # draws it, 5.54 m right of and above the world origin.
    origin, seen = projected
    assert seen[0] - origin[0] == pytest.approx(5.544445 * 48.6, rel=0.05)
    assert origin[1] - seen[1] == pytest.approx(5.544445 * 48.6, rel=0.05)
