"""The rqt web app's Foxglove page: how to connect, and whether foxglove_bridge runs.

Headless Chromium on the page while a real foxglove_bridge starts on a leased domain.
Screenshot: artifacts/rqt/foxglove.png.
"""

from __future__ import annotations

import socket
from pathlib import Path

import pytest

from ws_testing import RosProcess, executable, leased_domain, ros_environment
from ws_testing.browser import chromium_missing, launch_browser, screenshot, start_rqt


def test_foxglove_page_says_how_to_connect_and_sees_the_bridge(tmp_path: Path) -> None:
    reason = chromium_missing()
    if reason:
        pytest.skip(reason)
    from playwright.sync_api import sync_playwright

    with leased_domain() as domain:
        server, _ = start_rqt(ros_environment(domain), tmp_path / 'state')
        bridge = None
        try:
            with sync_playwright() as playwright:
                browser = launch_browser(playwright)
                try:
                    page = browser.new_page(viewport={'width': 1100, 'height': 700})
                    page.goto(server.page_url('/foxglove'))
                    page.wait_for_function('document.getElementById("foxglove-state")'
                                           '.textContent.includes("not running")',
                                           timeout=15000)
                    text = page.inner_text('main')
                    assert 'ros2 launch foxglove_bridge foxglove_bridge_launch.xml' in text
                    assert 'foxglove.sdk.v1' in text and 'foxglove.websocket.v1' in text

                    with socket.socket() as probe:  # a free port, as a user would pick one
                        probe.bind(('127.0.0.1', 0))
                        port = probe.getsockname()[1]
                    bridge = RosProcess([executable('foxglove_bridge', 'foxglove_bridge'),
                                         '--ros-args', '-p', f'port:={port}'], server.env,
                                        tmp_path / 'bridge.log')
                    bridge.wait_for_output(rf'Server listening on port {port}$', 20)
                    page.wait_for_function('document.getElementById("foxglove-state")'
                                           '.textContent.includes("is running")',
                                           timeout=20000)
                    url = page.inner_text('#foxglove-url')
                    assert url == f'ws://127.0.0.1:{port}', url
                    state = page.inner_text('#foxglove-state')
                    assert state == (f'foxglove_bridge is running (/foxglove_bridge), '
                                     f'port {port}.'), state
                    screenshot(page, 'foxglove')
                finally:
                    browser.close()
        finally:
            if bridge is not None:
                assert bridge.stop() == 0, bridge.output
            server.stop()
