"""The workspace's rosdep sources, written to a state directory: no network needed.

- `workspace.yaml`: a rule for every ROS package this environment has (the ament index of
  AMENT_PREFIX_PATH: the workspace's install and the ROS wheels): nothing to install.
- the package's `rules/base.yaml`: Python keys (pip, into the venv) and system keys (apt).
- `sources.list.d/10-workspace.list`: both, as file:// URLs.
- a rosdistro index with an empty jazzy distribution, so `rosdep update` has nothing to fetch.
"""

from __future__ import annotations

import hashlib
import os
from pathlib import Path

DISTRO = 'jazzy'


def ros_packages() -> list[str]:
    """Every package name in the ament index of AMENT_PREFIX_PATH."""
    names: set[str] = set()
    for prefix in os.environ.get('AMENT_PREFIX_PATH', '').split(os.pathsep):
        index = Path(prefix) / 'share' / 'ament_index' / 'resource_index' / 'packages'
        if index.is_dir():
            names.update(entry.name for entry in index.iterdir())
    return sorted(names)


def base_rules() -> Path:
    from ament_index_python.packages import get_package_share_directory
    return Path(get_package_share_directory('rosdep_workspace')) / 'rules' / 'base.yaml'


def write(state: Path) -> dict[str, str]:
    """Write the sources under `state`; the environment rosdep needs to use them (its cache
    goes to state/rosdep/sources.cache through ROS_HOME)."""
    state.mkdir(parents=True, exist_ok=True)
    workspace = ''.join(f"{name}: {{'*': {{pip: {{packages: []}}}}}}\n"
                        for name in ros_packages())
    _write_if_changed(state / 'workspace.yaml',
                      '# ROS packages present in this environment: nothing to install.\n'
                      + workspace)
    sources = state / 'sources.list.d'
    sources.mkdir(exist_ok=True)
    _write_if_changed(sources / '10-workspace.list',
                      f'yaml file://{state / "workspace.yaml"}\n'
                      f'yaml file://{base_rules()}\n')
    index = state / 'rosdistro'
    (index / DISTRO).mkdir(parents=True, exist_ok=True)
    _write_if_changed(index / DISTRO / 'distribution.yaml',
                      'release_platforms:\n  debian: [bookworm]\n  ubuntu: [noble]\n'
                      'repositories: {}\ntype: distribution\nversion: 2\n')
    _write_if_changed(index / 'index-v4.yaml',
                      f'distributions:\n  {DISTRO}:\n'
                      f'    distribution: [{DISTRO}/distribution.yaml]\n'
                      f'    distribution_status: active\n    distribution_type: ros2\n'
                      f'    python_version: 3\ntype: index\nversion: 4\n')
    return {'ROSDEP_SOURCE_PATH': str(sources),
            'ROSDISTRO_INDEX_URL': f'file://{index / "index-v4.yaml"}',
            'ROS_HOME': str(state), 'ROS_DISTRO': DISTRO, 'ROS_PYTHON_VERSION': '3'}


def fingerprint(state: Path) -> str:
    """Of everything `rosdep update` reads: a changed one means the cache is stale."""
    digest = hashlib.sha256()
    for path in (state / 'workspace.yaml', base_rules(),
                 state / 'sources.list.d' / '10-workspace.list'):
        digest.update(path.read_bytes())
    return digest.hexdigest()


def _write_if_changed(path: Path, text: str) -> None:
    if not path.is_file() or path.read_text() != text:
        path.write_text(text)
