"""joint_state_publisher_gui: the Joint State Publisher page in headless Chromium moves a
joint; the node publishes it (and its mimic joint) on /joint_states."""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

import pytest

from rqt_browser import CHROMIUM, SCREENSHOTS, chromium_missing
from support import REPO, Background, wait_until

pytestmark = pytest.mark.skipif(chromium_missing() is not None, reason=str(chromium_missing()))

ARM = REPO / 'tests' / 'data' / 'urdf' / 'test_arm.urdf'
URL = re.compile(r'Joint State Publisher: (http://127\.0\.0\.1:\d+/joint_state_publisher'
                 r'\?token=\w+)')
BROWSER_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--no-first-run']


def test_sliders_set_the_published_joint_states(launch, ros_env, probe, tmp_path: Path):
    from playwright.sync_api import sync_playwright
    from rclpy.qos import DurabilityPolicy, QoSProfile
    from sensor_msgs.msg import JointState
    from std_msgs.msg import String
    # The description latched on /robot_description, as robot_state_publisher offers it.
    description = probe.node.create_publisher(
        String, '/robot_description',
        QoSProfile(depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL))
    description.publish(String(data=ARM.read_text()))
    env = dict(ros_env, RQT_WEB_STATE_DIR=str(tmp_path / 'rqt'), BROWSER='')
    env.pop('DISPLAY', None)
    gui = launch('joint_state_publisher_gui', 'joint_state_publisher_gui', env=env)
    url = gui.wait_for_output(URL.pattern, timeout=40).group(1)
    states = probe.collect(JointState, '/joint_states')
    try:
        with sync_playwright() as playwright, Background(probe):
            browser = playwright.chromium.launch(executable_path=CHROMIUM, args=BROWSER_ARGS)
            page = browser.new_page()
            page.goto(url)
            page.wait_for_function('window.jsp && Object.keys(window.jsp.sliders).length === 3',
                                   timeout=20000)
            # One slider per movable joint that is no mimic, with the URDF's limits.
            assert page.evaluate('Object.keys(window.jsp.sliders)') == [
                'elbow_joint', 'slide_joint', 'wheel_joint']
            assert page.get_attribute('input[data-joint="slide_joint"]', 'min') == '0.5'
            page.evaluate('''() => { const s = document.querySelector(
                'input[data-joint="elbow_joint"]'); s.value = 0.5;
                s.dispatchEvent(new Event('input')); }''')

            def last() -> dict[str, float]:
                return dict(zip(states[-1].name, states[-1].position, strict=True)) \
                    if states else {}
            wait_until(lambda: abs(last().get('elbow_joint', 0) - 0.5) < 1e-9
                       and abs(last().get('follow_joint', 0) - 1.1) < 1e-9, 10,
                       'elbow_joint 0.5 (and its mimic 1.1) on /joint_states')
            page.click('#jsp-center')
            wait_until(lambda: last()['elbow_joint'] == 0.0, 10,
                       'Center: elbow_joint back to 0')
            SCREENSHOTS.mkdir(parents=True, exist_ok=True)
            page.screenshot(path=str(SCREENSHOTS / 'joint_state_publisher_gui.png'))
            browser.close()
    finally:
        subprocess.run(['rqt', '--stop'], env=env, capture_output=True, timeout=20)
