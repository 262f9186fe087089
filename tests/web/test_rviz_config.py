"""The RViz page's "Save Config As..." in headless Chromium: after loading a tutorial's .rviz
file, the saved file is upstream rviz2's layout (the keys and nesting of the tutorials' .rviz
files, and the rest of what rviz2 writes), keeps the loaded displays, options and view, and
the page loads it again as it loaded the original."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
import yaml

from rqt_browser import chromium_missing, launch_browser, start_rqt
from support import REPO, leased_domain, ros_environment

pytestmark = pytest.mark.skipif(chromium_missing() is not None, reason=str(chromium_missing()))

TUTORIAL_FILES = [REPO / 'src' / 'urdf_tutorial_r2d2' / 'urdf' / 'r2d2.rviz',
                  REPO / 'src' / 'urdf_tutorial' / 'rviz' / 'urdf.rviz',
                  REPO / 'src' / 'turtle_tf2_py' / 'rviz' / 'turtle_rviz.rviz']
READY = '() => window.rviz && window.rviz.ready && window.rviz.config'


def key_paths(node: Any, prefix: str = '') -> set[str]:
    """Every key path of a YAML tree ('Visualization Manager/Displays/*/Class'), list items
    as '*'."""
    paths = set()
    if isinstance(node, dict):
        for key, value in node.items():
            paths.add(prefix + key)
            paths |= key_paths(value, f'{prefix}{key}/')
    elif isinstance(node, list):
        for item in node:
            paths |= key_paths(item, f'{prefix}*/')
    return paths


def save_and_reload(page: Any, server: Any, config: Path, saved: Path) -> dict:
    """Open the page on `config`, save through the button; the page's state on the saved file."""
    page.goto(server.page_url('/rviz', config=str(config)))
    page.wait_for_function(READY, timeout=40000)
    with page.expect_download(timeout=20000) as download:
        page.click('#rviz-save')
    assert download.value.suggested_filename == config.name
    download.value.save_as(str(saved))
    page.goto(server.page_url('/rviz', config=str(saved)))
    page.wait_for_function(READY, timeout=40000)
    return page.evaluate('({config: window.rviz.config, fixedFrame: window.rviz.fixedFrame,'
                         ' displays: window.rviz.displays, status: window.rviz.status})')


def check_layout(saved: dict, original: dict) -> None:
    manager = saved['Visualization Manager']
    assert list(saved) == ['Panels', 'Visualization Manager', 'Window Geometry']
    assert [p['Class'] for p in saved['Panels']] == ['rviz_common/Displays', 'rviz_common/Views']
    assert manager['Class'] == '' and manager['Name'] == 'root'
    assert manager['Enabled'] is True and manager['Value'] is True
    assert set(manager['Global Options']) == {'Background Color', 'Fixed Frame', 'Frame Rate'}
    assert manager['Global Options'] == {**original['Visualization Manager']['Global Options'],
                                         'Frame Rate': 30}
    for display in manager['Displays']:
        assert {'Class', 'Enabled', 'Name', 'Value'} <= set(display), display
    assert all(isinstance(t, dict) and t['Class'].startswith('rviz_default_plugins/')
               for t in manager['Tools'])
    assert 'rviz_default_plugins/MoveCamera' in [t['Class'] for t in manager['Tools']]
    assert manager['Views']['Current']['Class'] == \
        original['Visualization Manager']['Views']['Current']['Class']
    assert {'Height', 'Width'} <= set(saved['Window Geometry'])
    # Every key the tutorials' files have at these levels, nested the same way.
    tutorial = set().union(*(key_paths(yaml.safe_load(f.read_text())) for f in TUTORIAL_FILES))
    wanted = {p for p in tutorial if p.count('/') <= 2 and not p.startswith('Panels/*/Property')}
    assert wanted - key_paths(saved) == set()
    # The loaded displays, with their settings (Topic: {Value: ...} nested as rviz2 does).
    originals = original['Visualization Manager']['Displays']
    assert [(d['Class'], d['Name']) for d in manager['Displays']] == \
        [(d['Class'], d['Name']) for d in originals]
    for before, after in zip(originals, manager['Displays'], strict=True):
        for key, value in before.items():
            if not isinstance(value, dict) or list(value) == ['Value']:
                assert after[key] == value, (before['Name'], key)


def test_save_config_writes_rviz2s_layout_and_loads_again(tmp_path: Path) -> None:
    # A file with a topic display too: a Marker's `Topic: {Value: ...}`.
    markers = tmp_path / 'markers.rviz'
    original = yaml.safe_load(TUTORIAL_FILES[0].read_text())
    original['Visualization Manager']['Displays'].append({
        'Class': 'rviz_default_plugins/Marker', 'Enabled': False, 'Name': 'Marker',
        'Namespaces': {}, 'Topic': {'Value': '/visualization_marker'}, 'Value': False})
    markers.write_text(yaml.safe_dump(original, sort_keys=False))
    with leased_domain() as domain:
        server, _ = start_rqt(ros_environment(domain), tmp_path / 'state')
        try:
            from playwright.sync_api import sync_playwright
            with sync_playwright() as playwright:
                browser = launch_browser(playwright)
                try:
                    page = browser.new_page(viewport={'width': 1280, 'height': 900},
                                            accept_downloads=True)
                    r2d2 = save_and_reload(page, server, TUTORIAL_FILES[0], tmp_path / 'a.rviz')
                    turtles = save_and_reload(page, server, TUTORIAL_FILES[2],
                                              tmp_path / 'b.rviz')
                    marker = save_and_reload(page, server, markers, tmp_path / 'c.rviz')
                finally:
                    browser.close()
        finally:
            server.stop()

    # r2d2.rviz: the layout, and the page shows the saved file as it showed the original.
    text = (tmp_path / 'a.rviz').read_text()
    assert '\n    Background Color: 48; 48; 48\n' in text  # plain, as rviz2 writes it
    assert '\n  Class: ""\n' in text
    saved = yaml.safe_load(text)
    check_layout(saved, yaml.safe_load(TUTORIAL_FILES[0].read_text()))
    robot = saved['Visualization Manager']['Displays'][1]
    assert robot['Description Topic'] == {'Value': '/robot_description'}
    assert robot['Alpha'] == 0.8
    view = saved['Visualization Manager']['Views']['Current']
    assert (view['Distance'], view['Pitch'], view['Yaw']) == pytest.approx((7, 0.6, 5.5),
                                                                           abs=1e-4)
    assert r2d2['fixedFrame'] == 'odom'
    assert [(d['class'], d['name'], d['enabled'], d['topic']) for d in r2d2['displays']] == [
        ('rviz_default_plugins/Grid', 'Grid', True, None),
        ('rviz_default_plugins/RobotModel', 'RobotModel', True, '/robot_description'),
        ('rviz_default_plugins/TF', 'TF', True, None)]
    assert r2d2['config']['background'] == [48, 48, 48]
    assert r2d2['config']['view']['Distance'] == pytest.approx(7, abs=1e-4)

    # turtle_rviz.rviz: its TopDownOrtho view (48.6 px/m around 0, 0) and display settings.
    saved = yaml.safe_load((tmp_path / 'b.rviz').read_text())
    check_layout(saved, yaml.safe_load(TUTORIAL_FILES[2].read_text()))
    view = saved['Visualization Manager']['Views']['Current']
    assert (view['Scale'], view['X'], view['Y']) == pytest.approx((48.6, 0, 0), abs=1e-3)
    assert turtles['fixedFrame'] == 'world'
    assert turtles['config']['view']['Class'] == 'rviz_default_plugins/TopDownOrtho'
    assert turtles['config']['view']['Scale'] == pytest.approx(48.6, abs=1e-3)
    grid = saved['Visualization Manager']['Displays'][0]
    assert (grid['Cell Size'], grid['Plane Cell Count'], grid['Color']) == (1, 10,
                                                                           '160; 160; 164')

    # A disabled Marker display on its topic: Enabled/Value false, Topic nested.
    saved = yaml.safe_load((tmp_path / 'c.rviz').read_text())
    check_layout(saved, original)
    assert saved['Visualization Manager']['Displays'][3] == {
        'Class': 'rviz_default_plugins/Marker', 'Enabled': False, 'Name': 'Marker',
        'Topic': {'Value': '/visualization_marker'}, 'Value': False}
    assert marker['displays'][3]['topic'] == '/visualization_marker'
    assert marker['displays'][3]['enabled'] is False
