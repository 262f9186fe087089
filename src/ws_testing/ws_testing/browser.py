"""Helpers for the rqt web app tests and benchmark: its server, and headless Chromium.

The browser is Debian's `chromium` driven by Playwright (never `playwright install`: no
internet); the server is started the way a learner starts it, with the `rqt` command.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import time
import urllib.error
import urllib.request
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from ws_testing.support import REPO, Background

CHROMIUM = '/usr/bin/chromium'
CHROMIUM_ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-background-networking',
                 '--disable-component-update', '--disable-sync', '--no-first-run']
SCREENSHOTS = REPO / 'artifacts' / 'rqt'
URL = re.compile(r'(http://127\.0\.0\.1:(\d+)/\S*\?token=(\w+))')


def chromium_missing() -> str | None:
    """Why the browser tests cannot run here, or None."""
    if not os.access(CHROMIUM, os.X_OK):
        return 'chromium not found: apt install chromium (scripts/test does it as root)'
    return None


@dataclass
class RqtServer:
    url: str  # the index page URL, with its token
    port: int
    token: str
    env: dict[str, str]

    def page_url(self, path: str, **query: str) -> str:
        extra = ''.join(f'&{k}={v}' for k, v in query.items())
        return f'http://127.0.0.1:{self.port}{path}?token={self.token}{extra}'

    def stop(self) -> None:
        subprocess.run(['rqt', '--stop'], env=self.env, capture_output=True, timeout=20)
        state_dir = Path(self.env['RQT_WEB_STATE_DIR'])
        for state in state_dir.glob('*.json'):  # in case --stop could not reach it
            try:
                os.kill(int(json.loads(state.read_text())['pid']), 9)
            except (OSError, ValueError, KeyError):
                pass


def start_rqt(env: dict[str, str], state_dir: Path, *args: str) -> tuple[RqtServer, str]:
    """Run `rqt --no-browser` with a private state dir; (the server, the command's output)."""
    env = dict(env, RQT_WEB_STATE_DIR=str(state_dir), BROWSER='')
    env.pop('DISPLAY', None)
    done = subprocess.run(['rqt', '--no-browser', *args], env=env, capture_output=True,
                          text=True, timeout=40)
    match = URL.search(done.stdout)
    if done.returncode != 0 or not match:
        raise AssertionError(f'rqt did not print a URL: {done.stdout}{done.stderr}')
    return RqtServer(match.group(1), int(match.group(2)), match.group(3), env), done.stdout


def http_status(url: str, headers: dict[str, str] | None = None) -> int:
    request = urllib.request.Request(url, headers=headers or {})
    try:
        with urllib.request.urlopen(request, timeout=10) as response:
            return response.status
    except urllib.error.HTTPError as error:
        return error.code


def launch_browser(playwright: Any) -> Any:
    return playwright.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS,
                                      headless=True)


def screenshot(page: Any, name: str) -> Path:
    SCREENSHOTS.mkdir(parents=True, exist_ok=True)
    path = SCREENSHOTS / f'{name}.png'
    page.screenshot(path=str(path), full_page=True)
    return path


def canvas_pixel(page: Any, x: int, y: int) -> tuple[int, int, int]:
    """RGB of the first turtlesim canvas in the page at pixel (x, y)."""
    data = page.evaluate(
        '([x, y]) => Array.from(document.querySelector("canvas.turtlesim")'
        '.getContext("2d").getImageData(x, y, 1, 1).data)', [x, y])
    return data[0], data[1], data[2]


def wait_for_pixel(page: Any, x: int, y: int, want: Any, timeout: float, what: str
                   ) -> tuple[int, int, int]:
    """Poll a canvas pixel until `want(rgb)` holds; fail naming `what` and the last colour."""
    deadline = time.monotonic() + timeout
    while True:
        rgb = canvas_pixel(page, x, y)
        if want(rgb):
            return rgb
        if time.monotonic() > deadline:
            raise AssertionError(f'{what}: pixel ({x}, {y}) is {rgb} after {timeout} s')
        page.wait_for_timeout(50)


def close_to(rgb: tuple[int, int, int], expected: tuple[int, int, int], tolerance: int = 12
             ) -> bool:
    return all(abs(a - b) <= tolerance for a, b in zip(rgb, expected, strict=True))


def copy_screenshots(target: Path) -> None:
    target.mkdir(parents=True, exist_ok=True)
    for path in SCREENSHOTS.glob('*.png'):
        shutil.copy(path, target / path.name)


# The RViz page's window in the tests (its screenshots' size).
VIEWPORT = {'width': 1280, 'height': 1000}


@contextmanager
def rviz_page(ros_env: dict[str, str], probe: Any, config: Path, tmp_path: Path,
              before_browser: Callable[[Any], None] | None = None) -> Iterator[tuple[Any, Any]]:
    """(rqt's server, its RViz page on `config` in headless Chromium), while a Background
    thread spins `probe`; `before_browser(server)` runs before the browser starts. All stopped
    afterwards."""
    from playwright.sync_api import sync_playwright
    server, _ = start_rqt(ros_env, tmp_path / 'state')
    try:
        with sync_playwright() as playwright, Background(probe):
            if before_browser is not None:
                before_browser(server)
            browser = launch_browser(playwright)
            try:
                page = browser.new_page(viewport=VIEWPORT)
                page.goto(server.page_url('/rviz', config=str(config)))
                yield server, page
            finally:
                browser.close()
    finally:
        server.stop()
