"""The "Using quality-of-service settings for lossy networks" demo page as written:
`ros2 run image_tools showimage` and `ros2 run image_tools cam2image --ros-args -p
burger_mode:=True` (reliable, then best effort), the frames on showimage's page of the rqt
web app in headless Chromium, upstream's one-line error for a QoS value it does not know,
and quality_of_service_demo_py's deadline, lifespan, liveliness and incompatible_qos.
Screenshot: artifacts/rqt/showimage.png."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from rqt_browser import chromium_missing, close_to, launch_browser, screenshot, start_rqt
from support import RosProcess

BURGER = ['ros2', 'run', 'image_tools', 'cam2image', '--ros-args', '-p', 'burger_mode:=True']


def test_showimage_shows_cam2image_burgers(tmp_path: Path, ros_env) -> None:
    reason = chromium_missing()
    if reason:
        pytest.skip(reason)
    from PIL import Image
    from playwright.sync_api import sync_playwright

    server, _ = start_rqt(ros_env, tmp_path / 'state')
    shown = RosProcess(['ros2', 'run', 'image_tools', 'showimage'], server.env,
                       tmp_path / 'showimage.log')
    camera = RosProcess(BURGER, server.env, tmp_path / 'cam2image.log')
    try:
        camera.wait_for_output(r'^\[INFO\] \[[\d.]+\] \[cam2image\]: Publishing image #1$',
                               timeout=20)
        shown.wait_for_output(r"\[showimage\]: Subscribing to topic 'image'", timeout=20)
        url = shown.wait_for_output(r'\[showimage\]: Showing the images at (\S+)').group(1)
        shown.wait_for_output(r'^\[INFO\] \[[\d.]+\] \[showimage\]: Received image '
                              r'#camera_frame\nReceived image #camera_frame$', timeout=20)
        with sync_playwright() as playwright:
            browser = launch_browser(playwright)
            try:
                page = browser.new_page(viewport={'width': 900, 'height': 700})
                page.goto(url)
                page.wait_for_function('() => window.rviz && window.rviz.images["/image"]'
                                       ' && window.rviz.images["/image"].drawn >= 3',
                                       timeout=30000)
                info = page.evaluate('window.rviz.images["/image"]')
                shot = screenshot(page, 'showimage')
                box = page.locator('canvas.rviz-image').bounding_box()
            finally:
                browser.close()
    finally:
        camera.stop()
        shown.stop()
        server.stop()
    assert (info['width'], info['height'], info['encoding']) == (320, 240, 'bgr8')
    # Burgers on black: the frame shows their bun colour (bgr 40, 140, 215 as RGB).
    image = Image.open(shot).convert('RGB').crop(
        (int(box['x']), int(box['y']), int(box['x'] + box['width']),
         int(box['y'] + box['height'])))
    colours = image.getcolors(maxcolors=1 << 16)
    bun = sum(n for n, rgb in colours if close_to(rgb, (215, 140, 40), 10))
    black = sum(n for n, rgb in colours if max(rgb) <= 10)
    assert bun > 500 and black > image.width * image.height // 2, (bun, black)


def test_best_effort_and_bad_qos_values(tmp_path: Path, ros_env) -> None:
    env = dict(ros_env, RQT_WEB_STATE_DIR=str(tmp_path / 'state'))
    best = ['--ros-args', '-p', 'reliability:=best_effort']
    shown = RosProcess(['ros2', 'run', 'image_tools', 'showimage', *best[:1], '-p',
                        'show_image:=false', *best[1:]], env, tmp_path / 'showimage.log')
    camera = RosProcess([*BURGER, '-p', 'reliability:=best_effort', '-p', 'frequency:=10.0'],
                        env, tmp_path / 'cam2image.log')
    bad_camera = RosProcess([*BURGER, '-p', 'reliability:=lossy'], env, tmp_path / 'bad1.log')
    bad_show = RosProcess(['ros2', 'run', 'image_tools', 'showimage', '--ros-args', '-p',
                           'history:=keep_some'], env, tmp_path / 'bad2.log')
    try:
        shown.wait_for_output(r'\[showimage\]: Received image #camera_frame', timeout=20)
        assert 'Showing the images' not in shown.output  # show_image:=false: no page
        assert bad_camera.wait(timeout=20) == 1 and bad_show.wait(timeout=20) == 1
    finally:
        for process in (camera, shown, bad_camera, bad_show):
            process.stop()
    # One line from the node, then ros2 run's own about the exit code.
    assert re.fullmatch(r"\[ERROR\] \[[\d.]+\] \[cam2image\]: Invalid QoS reliability setting "
                        r"'lossy'\n\[ros2run\]: Process exited with failure 1\n",
                        bad_camera.output), bad_camera.output
    assert re.fullmatch(r"\[ERROR\] \[[\d.]+\] \[showimage\]: Invalid QoS history setting "
                        r"'keep_some'\n\[ros2run\]: Process exited with failure 1\n",
                        bad_show.output), bad_show.output
    assert not (tmp_path / 'state').exists()  # bad input started no web app either


def test_quality_of_service_demo_py_nodes(launch, ros_env) -> None:
    demo = ['ros2', 'run', 'quality_of_service_demo_py']
    deadline = launch(argv=[*demo, 'deadline', '600', '--publish-for', '1500', '--pause-for',
                            '1500'], env=ros_env)
    lifespan = launch(argv=[*demo, 'lifespan', '1200', '--publish-count', '5',
                            '--subscribe-after', '3000'], env=ros_env)
    liveliness = launch(argv=[*demo, 'liveliness', '1000', '--kill-publisher-after', '1500'],
                        env=ros_env)
    incompatible = launch(argv=[*demo, 'incompatible_qos', 'durability'], env=ros_env)
    bad = launch(argv=[*demo, 'deadline', '-5'], env=ros_env)
    bad_override = launch(argv=[*demo, 'qos_overrides_talker', '--ros-args', '-p',
                                'qos_overrides./qos_overrides_chatter.publisher.depth:=20'],
                          env=ros_env)

    assert incompatible.wait(timeout=30) == 0
    assert incompatible.output.startswith(
        'Durability incompatibility selected.\nIncompatibility condition: publisher '
        'durability kind < subscription durability kind.\nSetting publisher durability to: '
        'VOLATILE\nSetting subscription durability to: TRANSIENT_LOCAL\n\n')
    assert re.search(r'\[talker\]: Offered incompatible qos - total 1 delta 1 '
                     r'last_policy_kind: rmw_qos_policy_kind_t\.RMW_QOS_POLICY_DURABILITY',
                     incompatible.output), incompatible.output
    assert re.search(r'\[listener\]: Requested incompatible qos - total 1 delta 1 '
                     r'last_policy_kind: rmw_qos_policy_kind_t\.RMW_QOS_POLICY_DURABILITY',
                     incompatible.output), incompatible.output
    deadline.wait_for_output(r"\[talker\]: Publishing: 'Talker says 0'")
    deadline.wait_for_output(r'\[listener\]: Listener heard: \[Talker says 0\]')
    deadline.wait_for_output(r'\[listener\]: Requested deadline missed - total 1 delta 1',
                             timeout=10)
    deadline.wait_for_output(r'\[talker\]: Offered deadline missed - total 1 delta 1')
    # AUTOMATIC: the talker's node destroyed after 1.5 s, its writer leaves the listener.
    liveliness.wait_for_output(r'\[listener\]: Liveliness changed event:\n.*\[listener\]:   '
                               r'alive_count: 0\n.*\n.*\[listener\]:   alive_count_change: -1',
                               timeout=15)
    lifespan.wait_for_output(r'\[listener\]: Listener starting up', timeout=15)
    lifespan.wait_for_output(r'\[listener\]: Listener heard: \[Talker says 4\]', timeout=5)
    assert 'Listener heard: [Talker says 0]' not in lifespan.output  # older than its lifespan
    assert bad.wait(timeout=20) == 2
    assert bad.output.splitlines()[-2:] == [
        'deadline: error: argument deadline: must be a positive integer, got -5',
        '[ros2run]: Process exited with failure 2'], bad.output
    assert bad_override.wait(timeout=20) == 1
    assert re.fullmatch(r'\[ERROR\] \[[\d.]+\] \[qos_overrides_talker\]: Provided QoS overrides '
                        r'for publisher `/qos_overrides_chatter` with id `None`, are not valid: '
                        r'expected qos depth less than 10\n\[ros2run\]: Process exited with '
                        r'failure 1\n', bad_override.output), bad_override.output
