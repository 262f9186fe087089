"""scripts/setup: a second run changes nothing; a missing prerequisite is one clear line."""

import os
import subprocess
from pathlib import Path

from support import REPO


def run_setup(env=None):
    return subprocess.run([str(REPO / 'scripts' / 'setup')], capture_output=True, text=True,
                          env=env, timeout=600)


def test_second_run_builds_nothing():
    run_setup()  # whatever the state, after this the workspace is current
    marker = REPO / 'install' / '.source-fingerprint'
    before = marker.stat().st_mtime_ns
    result = run_setup()
    assert result.returncode == 0, result.stderr
    assert result.stdout.strip() == 'setup: workspace up to date'
    assert 'Starting >>>' not in result.stdout + result.stderr
    assert marker.stat().st_mtime_ns == before


def test_missing_cmake_is_reported_in_one_line(tmp_path):
    # A PATH holding every usual tool except cmake.
    bin_dir = tmp_path / 'bin'
    bin_dir.mkdir()
    for directory in ('/usr/local/bin', '/usr/bin', '/bin'):
        for tool in Path(directory).iterdir():
            link = bin_dir / tool.name
            if tool.name != 'cmake' and not link.exists():
                link.symlink_to(tool)
    env = dict(os.environ, PATH=str(bin_dir))
    result = run_setup(env)
    assert result.returncode == 1
    assert result.stderr.splitlines() == [
        'setup: cmake not found -- fix: install cmake 3.16 or newer (e.g. apt install cmake)']


def test_unknown_argument_is_reported_in_one_line():
    result = subprocess.run([str(REPO / 'scripts' / 'setup'), '--everything'], capture_output=True,
                            text=True, timeout=60)
    assert result.returncode == 1
    assert result.stderr.splitlines() == [
        "setup: unknown argument '--everything' (allowed: --demo, --tests or nothing) -- fix: "
        'run scripts/setup, scripts/setup --demo or scripts/setup --tests']
    assert result.stdout == ''
