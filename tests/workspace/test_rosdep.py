""""Managing Dependencies with rosdep" on this stack: PyPI's rosdep with the workspace's own
sources, offline. A package made by `ros2 pkg create` declares a ROS package of this
environment (rclpy, turtlesim), Python keys (one installed, one not), a system key and a key
no rule knows; `rosdep init/update/keys/resolve/check/install` answer as the page shows,
without network and without running apt.
"""
from __future__ import annotations

import re
import subprocess
from pathlib import Path

import pytest

from support import run_checked

DEPENDS = ['python3-numpy', 'python3-transforms3d', 'libpcl-all-dev', 'no_such_key']


@pytest.fixture
def workspace(tmp_path, ros_env) -> tuple[Path, dict[str, str]]:
    env = dict(ros_env, ROSDEP_WORKSPACE_STATE=str(tmp_path / 'rosdep'))
    src = tmp_path / 'src'
    src.mkdir()
    run_checked(['ros2', 'pkg', 'create', '--build-type', 'ament_python', '--license',
                 'Apache-2.0', 'my_pkg', '--dependencies', 'rclpy', 'turtlesim'], src, env)
    xml = src / 'my_pkg' / 'package.xml'
    xml.write_text(xml.read_text().replace('  <test_depend>', ''.join(
        f'  <exec_depend>{key}</exec_depend>\n' for key in DEPENDS) + '  <test_depend>', 1))
    return tmp_path, env


def rosdep(root: Path, env: dict[str, str], *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(['rosdep', *args], cwd=root, env=env, capture_output=True, text=True,
                          timeout=60, stdin=subprocess.DEVNULL)


def drop(root: Path, key: str) -> None:
    xml = root / 'src' / 'my_pkg' / 'package.xml'
    xml.write_text(xml.read_text().replace(f'  <exec_depend>{key}</exec_depend>\n', ''))


def test_rosdep_page_offline(workspace) -> None:
    root, env = workspace
    init = rosdep(root, env, 'init')
    assert init.returncode == 0 and 'nothing to initialize' in init.stdout, init
    update = rosdep(root, env, 'update')
    assert update.returncode == 0, update
    assert re.search(r'Hit file://\S+/workspace\.yaml', update.stdout), update.stdout
    assert 'https://' not in update.stdout  # nothing from the network

    keys = rosdep(root, env, 'keys', '--from-paths', 'src')
    assert set(keys.stdout.split()) == {*DEPENDS, 'rclpy', 'turtlesim', 'python3-pytest',
                                        'ament_copyright', 'ament_flake8', 'ament_pep257'}
    # --ignore-src: packages found on AMENT_PREFIX_PATH (the workspace, the wheels) drop out.
    keys = rosdep(root, env, 'keys', '--from-paths', 'src', '--ignore-src')
    assert set(keys.stdout.split()) == {*DEPENDS, 'python3-pytest'}
    assert rosdep(root, env, 'resolve', 'rclpy').stdout.split() == ['#pip']  # nothing to do
    assert rosdep(root, env, 'resolve', 'python3-numpy').stdout.split() == ['#pip', 'numpy']
    assert rosdep(root, env, 'resolve', 'libpcl-all-dev').stdout.split() == ['#apt',
                                                                            'libpcl-dev']

    unknown = rosdep(root, env, 'install', '--from-paths', 'src', '-y', '--ignore-src')
    assert unknown.returncode == 1
    assert unknown.stderr == (
        "rosdep: my_pkg depends on 'no_such_key', which no rule resolves (not a ROS package of "
        "this environment, not in rosdep_workspace's rules) -- fix: correct the key in "
        'my_pkg/package.xml, or add a rule (docs/rosdep.md)\n')
    unknown = rosdep(root, env, 'check', '--from-paths', 'src', '--ignore-src')
    assert unknown.returncode == 1
    assert unknown.stderr.startswith("rosdep: my_pkg depends on 'no_such_key', which no rule "
                                     'resolves'), unknown.stderr
    drop(root, 'no_such_key')

    # Without --ignore-src the ROS packages resolve through the workspace's rules: installed.
    check = rosdep(root, env, 'check', '--from-paths', 'src')
    assert check.returncode == 1
    assert check.stdout == ('System dependencies have not been satisfied:\n'
                            'pip\ttransforms3d\napt\tlibpcl-dev\n'), check.stdout
    simulated = rosdep(root, env, 'install', '--from-paths', 'src', '-y', '--ignore-src', '-s')
    assert re.search(r'#\[pip\] Installation commands:\n  \S*pip\S* install -U transforms3d\n',
                     simulated.stdout), simulated.stdout

    refused = rosdep(root, env, 'install', '--from-paths', 'src', '-y', '--ignore-src',
                     '--skip-keys', 'python3-transforms3d')
    assert refused.returncode == 1
    assert refused.stdout == (
        "rosdep: libpcl-dev is a system package, which this workspace's rosdep does not install: "
        'run `sudo apt-get install libpcl-dev`\n'
        'rosdep: 1 system package(s) left for you to install (above); everything else is '
        'installed\n'), refused.stdout

    drop(root, 'libpcl-all-dev')
    drop(root, 'python3-transforms3d')
    done = rosdep(root, env, 'install', '--from-paths', 'src', '-y', '--ignore-src')
    assert done.returncode == 0, done
    assert done.stdout == '#All required rosdeps installed successfully\n'


def test_every_key_of_this_workspace_resolves(ros_env, tmp_path) -> None:
    """The page's commands typed in this workspace itself: each key its packages declare is
    a ROS package of the environment or has a rule (a new dependency needs one)."""
    env = dict(ros_env, ROSDEP_WORKSPACE_STATE=str(tmp_path / 'rosdep'))
    repo = Path(__file__).resolve().parents[2]
    check = rosdep(repo, env, 'check', '--from-paths', 'src', '--ignore-src')
    assert 'no rule resolves' not in check.stderr, check.stderr
    # Only system packages (the apt ones setup does not install) may be left to install.
    left = check.stdout.splitlines()[1:] if check.returncode else []
    assert all(line.startswith('apt\t') for line in left), check.stdout
