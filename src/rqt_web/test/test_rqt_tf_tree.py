"""rqt_tf_tree without X: the TF Tree page of the rqt web app, in headless Chromium.

Real broadcasters (tf2_ros' static_transform_publisher, the tutorial's turtle and carrot
broadcasters with a headless turtlesim) on a leased domain; the page must show each frame
under its parent with rqt_tf_tree's edge labels. Screenshot: artifacts/rqt/tf_tree.png.
"""

from __future__ import annotations

import json
import re
import urllib.request
from pathlib import Path

import pytest

from ws_testing import RosProcess, executable, leased_domain, ros2, ros_environment
from ws_testing.browser import chromium_missing, launch_browser, screenshot, start_rqt

EXPECTED_EDGES = {('world', 'mystaticturtle'), ('world', 'turtle1'), ('turtle1', 'carrot1')}


def test_tf_tree_page_shows_the_live_frames(tmp_path: Path) -> None:
    reason = chromium_missing()
    if reason:
        pytest.skip(reason)
    from playwright.sync_api import sync_playwright

    with leased_domain() as domain:
        env = ros_environment(domain)
        server, _ = start_rqt(env, tmp_path / 'state')
        processes: list[RosProcess] = []

        def start(name: str, argv: list[str]) -> RosProcess:
            process = RosProcess(argv, server.env, tmp_path / f'{name}.log')
            processes.append(process)
            return process
        try:
            opened = ros2(server.env, 'run', 'rqt_tf_tree', 'rqt_tf_tree', '--no-browser')
            assert opened.returncode == 0, opened.stderr
            assert opened.stdout.startswith(f'rqt: TF Tree: {server.page_url("/tf_tree")} '
                                            '(web app already running)'), opened.stdout

            start('static', ['ros2', 'run', 'tf2_ros', 'static_transform_publisher', '--z', '1',
                             '--frame-id', 'world', '--child-frame-id', 'mystaticturtle'])
            start('turtlesim', [executable('turtlesim', 'turtlesim_node'), '--headless'])
            start('broadcaster', [executable('turtle_tf2_py', 'turtle_tf2_broadcaster'),
                                  '--ros-args', '-p', 'turtlename:=turtle1'])
            start('carrot', [executable('turtle_tf2_py', 'fixed_frame_tf2_broadcaster')])

            with sync_playwright() as playwright:
                browser = launch_browser(playwright)
                try:
                    page = browser.new_page(viewport={'width': 1280, 'height': 900})
                    page.goto(server.page_url('/tf_tree'))
                    page.wait_for_function(
                        '() => window.rqtTfTree && window.rqtTfTree.edges.length >= 3 '
                        '&& window.rqtTfTree.edges.every((e) => !e[2].includes("undefined"))',
                        timeout=30000)
                    # Two refreshes later the rates are averages over a few samples.
                    page.wait_for_timeout(2500)
                    tree = page.evaluate('window.rqtTfTree')
                    shot = screenshot(page, 'tf_tree')
                finally:
                    browser.close()
            assert sorted(tree['frames']) == ['carrot1', 'mystaticturtle', 'turtle1', 'world']
            edges = {(parent, child): label for parent, child, label in tree['edges']}
            assert set(edges) == EXPECTED_EDGES, edges
            static = edges[('world', 'mystaticturtle')].split('\n')
            assert static[0] == 'Broadcaster: default_authority'
            assert static[1:] == ['Average rate: 10000.0', 'Buffer length: 0.0',
                                  'Most recent transform: 0.0', 'Oldest transform: 0.0']
            for edge, low, high in ((('world', 'turtle1'), 20, 100),
                                    (('turtle1', 'carrot1'), 5, 15)):
                label = edges[edge]
                rate = float(re.search(r'Average rate: ([\d.]+)', label).group(1))
                assert low < rate < high, label  # turtlesim poses at 62.5 Hz, carrot at 10 Hz
                assert float(re.search(r'Buffer length: ([\d.]+)', label).group(1)) > 0.5
                assert float(re.search(r'Most recent transform: ([\d.]+)', label).group(1)) > 1e9
            assert shot.stat().st_size > 10000
            _check_poses_api(server)
        finally:
            for process in reversed(processes):
                process.stop()
            server.stop()


def _check_poses_api(server) -> None:
    """The RViz page's one request: poses, parents and a version; with `after`, the answer
    waits for newer tf data (turtle1 comes at 62.5 Hz here, so it is newer at once)."""
    def get(query: str) -> dict:
        url = server.page_url('/api/tf/poses', fixed_frame='world') + query
        with urllib.request.urlopen(url, timeout=10) as response:
            return json.loads(response.read())

    first = get('')
    assert first['parents'] == {'mystaticturtle': 'world', 'turtle1': 'world',
                                'carrot1': 'turtle1'}, first['parents']
    assert first['poses']['mystaticturtle']['translation'] == [0.0, 0.0, 1.0]
    newer = get(f'&after={first["version"]}')
    assert newer['version'] > first['version'], (first['version'], newer['version'])
    assert sorted(newer['poses']) == ['carrot1', 'mystaticturtle', 'turtle1', 'world']
