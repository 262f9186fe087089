"""rqt in the browser: the pages in headless Chromium against real nodes, as a learner uses them.

One server (started with the `rqt` command), one headless turtlesim and one browser serve
every test of this module; tests run in file order and build on each other (turtle2 is
spawned once, then driven, then run into a wall). Screenshots go to artifacts/rqt/.
"""

from __future__ import annotations

import math
import time
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from ws_testing import RosProcess, TestNode, executable, leased_domain, ros2, ros_environment
from ws_testing.browser import (
    RqtServer,
    canvas_pixel,
    chromium_missing,
    close_to,
    http_status,
    launch_browser,
    screenshot,
    start_rqt,
    wait_for_pixel,
)

SHELLS = [(46, 139, 87), (34, 120, 60), (85, 107, 47), (0, 128, 128), (107, 142, 35),
          (60, 110, 160), (139, 90, 43), (120, 80, 150), (176, 120, 40), (70, 130, 80)]
PPM = 45.0  # canvas pixels per metre
TURTLE2 = (2.0, 2.0)  # where the learner spawns turtle2 (metres)


@dataclass
class World:
    server: RqtServer
    env: dict[str, str]
    turtlesim: RosProcess
    probe: TestNode
    browser: Any
    tmp: Path

    def page(self, path: str, **query: str) -> Any:
        page = self.browser.new_page(viewport={'width': 1280, 'height': 900})
        page.goto(self.server.page_url(path, **query))
        page.wait_for_function('document.getElementById("status").textContent === "connected"',
                               timeout=15000)
        return page


@pytest.fixture(scope='module')
def world(tmp_path_factory: pytest.TempPathFactory) -> Iterator[World]:
    reason = chromium_missing()
    if reason:
        pytest.skip(reason)
    from playwright.sync_api import sync_playwright

    tmp = tmp_path_factory.mktemp('rqt')
    with leased_domain() as domain:
        server, _ = start_rqt(ros_environment(domain), tmp / 'state')
        turtlesim = RosProcess([executable('turtlesim', 'turtlesim_node'), '--headless',
                                '--canvas-png', str(tmp / 'canvas.png')], server.env,
                               tmp / 'turtlesim.log')
        probe = TestNode(domain)
        try:
            with sync_playwright() as playwright:
                browser = launch_browser(playwright)
                try:
                    yield World(server, server.env, turtlesim, probe, browser, tmp)
                finally:
                    browser.close()
        finally:
            probe.close()
            turtlesim.stop()
            server.stop()


def submit(page: Any, field: str, value: str, button: str, outcome: str) -> str:
    """Type `value` into `field`, click `button`, wait for an 'ok' or 'error' message."""
    page.fill(field, value)
    page.click(button)
    page.wait_for_selector(f'#message .{outcome}', timeout=10000)
    return page.inner_text('#message')


def test_headless_turtlesim_prints_its_live_view_url(world: World) -> None:
    match = world.turtlesim.wait_for_output(r'Live view: (http://\S+)', timeout=20)
    assert match.group(1) == world.server.page_url('/turtlesim')


def test_requests_without_token_or_from_other_sites_are_refused(world: World) -> None:
    server = world.server
    base = f'http://127.0.0.1:{server.port}'
    assert http_status(server.page_url('/graph')) == 200
    assert http_status(f'{base}/graph') == 403
    assert http_status(f'{base}/api/graph') == 403
    assert http_status(f'{base}/ws', {'Connection': 'Upgrade', 'Upgrade': 'websocket'}) == 403
    assert http_status(f'{base}/graph?token=wrong') == 403
    # Another site's page (cross-site request, or a DNS-rebinding name for 127.0.0.1).
    assert http_status(server.page_url('/api/graph'), {'Origin': 'http://evil.example'}) == 403
    assert http_status(server.page_url('/api/graph'), {'Host': f'evil.example:{server.port}'}) \
        == 403
    assert http_status(server.page_url('/ws'), {
        'Origin': 'http://evil.example', 'Connection': 'Upgrade', 'Upgrade': 'websocket',
        'Sec-WebSocket-Version': '13', 'Sec-WebSocket-Key': 'dGhlIHNhbXBsZSBub25jZQ=='}) == 403


def test_every_tutorial_command_opens_its_page_of_the_same_app(world: World) -> None:
    env = world.env
    for package, page in (('rqt_graph', '/graph'), ('rqt_console', '/console'),
                          ('rqt_service_caller', '/services'),
                          ('rqt_reconfigure', '/parameters'), ('rqt_topic', '/topics')):
        done = ros2(env, 'run', package, package, '--no-browser')
        assert done.returncode == 0, done.stderr
        assert f':{world.server.port}{page}?token={world.server.token}' in done.stdout
        assert 'already running' in done.stdout
    import subprocess
    done = subprocess.run(['rqt_graph'], env=env, capture_output=True, text=True, timeout=30)
    assert f':{world.server.port}/graph?token=' in done.stdout, done.stdout + done.stderr
    assert 'no display here' in done.stdout  # no browser to open: says so, exit code 0
    assert done.returncode == 0
    done = subprocess.run(['rqt'], env=env, capture_output=True, text=True, timeout=30)
    assert done.stdout.startswith(f'rqt: http://127.0.0.1:{world.server.port}/?token='), \
        done.stdout + done.stderr


def test_graph_shows_turtlesim_and_controller_joined_by_their_topics(world: World) -> None:
    controller = RosProcess([executable('my_robot_controller', 'turtle_controller')], world.env,
                            world.tmp / 'controller.log')
    try:
        page = world.page('/graph')
        wanted = [['/turtle_controller', '/turtle1/cmd_vel'], ['/turtle1/cmd_vel', '/turtlesim'],
                  ['/turtlesim', '/turtle1/pose'], ['/turtle1/pose', '/turtle_controller']]
        page.wait_for_function(
            '(wanted) => window.rqtGraph && wanted.every(([a, b]) => '
            'window.rqtGraph.edges.some(([s, t]) => s === a && t === b))', arg=wanted,
            timeout=20000)
        shown = page.evaluate('window.rqtGraph')
        assert '/rosout' not in shown['nodes']  # Hide debug is on by default
        screenshot(page, 'graph')
        for button, name, start in (('#export-svg', 'rosgraph.svg', b'<svg'),
                                    ('#export-png', 'rosgraph.png', b'\x89PNG')):
            with page.expect_download() as download:
                page.click(button)
            assert download.value.suggested_filename == name
            assert Path(download.value.path()).read_bytes().startswith(start)
        # Clicking a node lists what it offers, services included (not drawn, as upstream).
        x, y = page.evaluate('(() => { const p = window.rqtCy.$(\'node[label="/turtlesim"]\')'
                             '.renderedPosition(); const box = document.getElementById("cy")'
                             '.getBoundingClientRect(); return [box.x + p.x, box.y + p.y]; })()')
        page.mouse.click(x, y)
        page.wait_for_function('document.getElementById("node-details").textContent'
                               '.includes("/turtle1/set_pen: turtlesim/srv/SetPen")', timeout=5000)
        page.select_option('#mode', 'nodes')
        page.wait_for_function(
            'window.rqtGraph.edges.some(([s, t, label]) => s === "/turtle_controller" && '
            't === "/turtlesim" && label.includes("/turtle1/cmd_vel"))', timeout=5000)
        page.select_option('#mode', 'active')
        controller.stop()
        # The graph follows by itself when a node leaves.
        page.wait_for_function('!window.rqtGraph.nodes.includes("/turtle_controller")',
                               timeout=10000)
        page.close()
    finally:
        controller.stop()


def test_service_caller_spawns_and_sets_pen_and_arrow_keys_drive(world: World) -> None:
    from turtlesim.msg import Pose

    canvas = world.page('/turtlesim')
    canvas.wait_for_selector('canvas.turtlesim', timeout=15000)
    services = world.page('/services', service='/spawn')
    services.wait_for_selector('input[name="name"]', timeout=15000)
    x, y = TURTLE2
    services.fill('input[name="x"]', str(x))
    services.fill('input[name="y"]', str(y))
    services.fill('input[name="theta"]', '0')
    services.fill('input[name="name"]', 'turtle2')
    services.click('#call')
    services.wait_for_function('document.getElementById("response").textContent'
                               '.includes("name: \\"turtle2\\"")', timeout=15000)
    screenshot(services, 'service_caller_spawn')
    # turtle2 appears on the live canvas: its shell, right of the shell's centre lines.
    px, py = round(x * PPM) + 5, round(500 - y * PPM) + 5
    wait_for_pixel(canvas, px, py, lambda rgb: any(close_to(rgb, s, 20) for s in SHELLS),
                   10, 'turtle2 on the canvas')

    # set_pen: an out-of-range value is refused in the page, nothing is sent.
    services.select_option('#service', '/turtle2/set_pen')
    services.wait_for_selector('input[name="width"]', timeout=10000)
    for field, value in (('g', '0'), ('b', '0'), ('width', '8'), ('off', '0')):
        services.fill(f'input[name="{field}"]', value)
    refused = submit(services, 'input[name="r"]', '300', '#call', 'error')
    assert "'r' must be an integer in [0, 255], got 300" in refused
    assert 'Not sent' in refused
    screenshot(services, 'service_caller_out_of_range')
    submit(services, 'input[name="r"]', '255', '#call', 'ok')

    # Arrow keys in the page drive turtle2 forward; the trail behind it is red.
    poses = world.probe.collect(Pose, '/turtle2/pose')
    canvas.select_option('select.turtle', '/turtle2')
    canvas.click('canvas.turtlesim')
    for _ in range(3):
        canvas.keyboard.press('ArrowUp')
        canvas.wait_for_timeout(250)
    world.probe.spin_until(lambda: any(p.x > x + 1.0 for p in poses), 10,
                           'turtle2 driving forward (pose x)')
    wait_for_pixel(canvas, round((x + 0.5) * PPM), round(500 - y * PPM),
                   lambda rgb: close_to(rgb, (255, 0, 0), 30), 10, 'red trail behind turtle2')
    screenshot(canvas, 'turtlesim_teleop')
    # R: rotate_absolute to pi/2 (a goal, as turtle_teleop_key sends it).
    canvas.keyboard.press('r')
    world.probe.spin_until(lambda: poses and abs(poses[-1].theta - 1.5708) < 0.05, 10,
                           'turtle2 turned to theta = pi/2 by the R key')
    canvas.close()
    services.close()


def test_parameter_set_changes_the_background(world: World) -> None:
    canvas = world.page('/turtlesim')
    canvas.wait_for_selector('canvas.turtlesim', timeout=15000)
    wait_for_pixel(canvas, 3, 3, lambda rgb: close_to(rgb, (69, 86, 255), 2), 10,
                   'default background')
    params = world.page('/parameters', node='/turtlesim')
    params.wait_for_selector('input[data-name="background_r"]', timeout=15000)
    field, button = 'input[data-name="background_r"]', 'button[data-name="background_r"]'
    assert 'must be in [0, 255], got 300' in submit(params, field, '300', button, 'error')
    submit(params, field, '0', button, 'ok')
    wait_for_pixel(canvas, 3, 3, lambda rgb: close_to(rgb, (0, 86, 255), 2), 10,
                   'background after setting background_r to 0')
    screenshot(params, 'parameters')
    screenshot(canvas, 'turtlesim_background')
    assert canvas_pixel(canvas, 3, 3) == (0, 86, 255)
    params.close()
    canvas.close()


def test_console_shows_the_wall_warning(world: World) -> None:
    from geometry_msgs.msg import Twist

    console = world.page('/console')
    publisher = world.probe.node.create_publisher(Twist, '/turtle2/cmd_vel', 10)
    backwards = Twist()
    backwards.linear.x = -3.0
    deadline = time.monotonic() + 3.0
    while time.monotonic() < deadline:  # turtle2 (x about 3 m) backs into the left wall
        publisher.publish(backwards)
        world.probe.spin_for(0.1)
    console.wait_for_function(
        'Array.from(document.querySelectorAll("#log tr")).some(row => '
        'row.textContent.includes("Oh no! I hit the wall!") && row.textContent.includes("WARN"))',
        timeout=10000)
    screenshot(console, 'console')
    console.uncheck('input[data-level="WARN"]')
    console.wait_for_function('!document.getElementById("log").textContent.includes("Oh no!")',
                              timeout=5000)
    console.check('input[data-level="WARN"]')
    # turtle2 keeps hitting the wall for turtlesim's 1 s cmd_vel timeout, and a repeated
    # warning is logged at most once a second: only later is every wall warning logged.
    world.probe.spin_for(max(0.0, 2.5 - (time.monotonic() - deadline)))
    console.click('#clear')
    console.wait_for_function('document.querySelectorAll("#log tr").length === 0', timeout=5000)
    console.close()


def test_topics_page_monitors_and_publishes(world: World) -> None:
    from turtlesim.msg import Pose

    page = world.page('/topics')
    page.wait_for_selector('input[data-topic="/turtle1/pose"]', timeout=15000)
    page.check('input[data-topic="/turtle1/pose"]')
    row = 'tr[data-topic="/turtle1/pose"]'
    page.wait_for_function(f'Number(document.querySelector(\'{row} .hz\').textContent) > 20',
                           timeout=10000)
    assert 'theta:' in page.inner_text(f'{row} .latest')
    poses = world.probe.collect(Pose, '/turtle1/pose')
    world.probe.spin_until(lambda: bool(poses), 10, 'a turtle1 pose')
    start = poses[-1]
    page.fill('#pub-topic', '/turtle1/cmd_vel')
    page.fill('#pub-type', 'geometry_msgs/msg/Twist')
    page.press('#pub-type', 'Tab')
    page.wait_for_selector('input[name="linear.x"]', timeout=10000)
    field = 'input[name="linear.x"]'
    assert "'linear.x' must be a finite number" in submit(page, field, 'fast', '#publish',
                                                          'error')
    submit(page, field, '-1.5', '#publish', 'ok')
    world.probe.spin_until(
        lambda: math.hypot(poses[-1].x - start.x, poses[-1].y - start.y) > 0.3, 10,
        'turtle1 moving after the published Twist')
    screenshot(page, 'topics')
    page.close()


def test_actions_page_sends_a_goal_and_cancels_one(world: World) -> None:
    page = world.page('/actions')
    page.wait_for_function('Array.from(document.querySelectorAll("#action option"))'
                           '.some(o => o.value === "/turtle1/rotate_absolute")', timeout=15000)
    page.select_option('#action', '/turtle1/rotate_absolute')
    page.wait_for_selector('input[name="theta"]', timeout=10000)
    page.fill('input[name="theta"]', '2.5')
    page.click('#send-goal')
    page.wait_for_function('document.getElementById("goal-status").textContent'
                           '.includes("SUCCEEDED")', timeout=15000)
    assert 'delta:' in page.inner_text('#result')
    assert 'remaining:' in page.inner_text('#feedback')
    screenshot(page, 'actions')
    # 3.1 rad from 2.5 the short way (-2.5 was only 1.3 rad): seconds in which to cancel.
    page.fill('input[name="theta"]', '-0.6')
    page.click('#send-goal')
    page.wait_for_function('document.getElementById("goal-status").textContent'
                           '.includes("accepted")', timeout=10000)
    page.click('#cancel-goal')
    page.wait_for_function('document.getElementById("goal-status").textContent'
                           '.includes("CANCELED")', timeout=10000)
    page.close()


def test_without_npm_libraries_only_the_graph_page_is_unavailable(world: World) -> None:
    env = dict(world.env, RQT_WEB_JS_DIR=str(world.tmp / 'no-npm'))
    server, _ = start_rqt(env, world.tmp / 'state-no-npm')
    try:
        page = world.browser.new_page()
        page.goto(server.page_url('/graph'))
        page.wait_for_selector('#graph-unavailable', timeout=15000)
        assert 'Install npm and rerun scripts/setup' in page.inner_text('#graph-unavailable')
        page.goto(server.page_url('/services'))
        page.wait_for_function('document.querySelectorAll("#service option").length > 0',
                               timeout=15000)
        page.close()
    finally:
        server.stop()
