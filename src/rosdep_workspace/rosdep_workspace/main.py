"""`rosdep`: PyPI's rosdep on this workspace's sources, offline (docs/rosdep.md).

Every verb is rosdep's own (`keys`, `resolve`, `check`, `install`, `update`, `db`...), with
three differences: `init` has nothing to do (the sources are the workspace's), the cache is
refreshed offline whenever the workspace's packages change, and `install` never runs apt:
each system package it would install is named, once, with the command that installs it.
"""

from __future__ import annotations

import io
import os
import re
import sys
from contextlib import redirect_stderr, redirect_stdout
from pathlib import Path

from rosdep_workspace import pip_detection, sources

STATE_ENV = 'ROSDEP_WORKSPACE_STATE'
# `install` and `keys` say `pkg: Cannot locate...`, `check` says `ERROR[pkg]: Cannot locate...`.
MISSING_KEY = re.compile(r'^(?:ERROR\[)?([^\s\[\]:]+)\]?: Cannot locate rosdep definition for '
                         r'\[([^\]]+)\]$', re.MULTILINE)


def state_dir() -> Path:
    """Where the sources and cache live: the venv's (this workspace's) rosdep directory."""
    if os.environ.get(STATE_ENV):
        return Path(os.environ[STATE_ENV])
    return Path(sys.prefix) / 'rosdep'


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    state = state_dir()
    os.environ.update(sources.write(state))
    if argv[:1] == ['init']:
        print(f'rosdep: this workspace keeps its sources in {state / "sources.list.d"} '
              '(ROSDEP_SOURCE_PATH): nothing to initialize; run `rosdep update`')
        return 0
    from rosdep2 import main as rosdep
    pip_detection.use_metadata()
    if argv[:1] != ['update']:
        _refresh_cache(state, rosdep)
    if argv[:1] == ['install']:
        return _install_without_apt(rosdep, argv)
    return _run(rosdep, argv)


def _run(rosdep, argv: list[str]) -> int:
    """rosdep's main; its report of keys without a rule becomes one line per key."""
    errors = io.StringIO()
    try:
        with redirect_stderr(errors):
            rosdep.rosdep_main(argv)
        code = 0
    except SystemExit as done:
        code = done.code if isinstance(done.code, int) else (0 if done.code is None else 1)
    text = errors.getvalue()
    missing = dict.fromkeys(MISSING_KEY.findall(text))
    if not missing:
        print(text, end='', file=sys.stderr)
    for package, key in missing:
        print(f"rosdep: {package} depends on '{key}', which no rule resolves (not a ROS package "
              "of this environment, not in rosdep_workspace's rules) -- fix: correct the key in "
              f'{package}/package.xml, or add a rule (docs/rosdep.md)', file=sys.stderr)
    return code


def _refresh_cache(state: Path, rosdep) -> None:
    """`rosdep update` (offline, ~1 s) when the sources changed since the last one."""
    stamp = state / 'sources.fingerprint'
    current = sources.fingerprint(state)
    if stamp.is_file() and stamp.read_text() == current:
        return
    # Quiet: rosdep's progress lines and its warning about root (the cache is the venv's).
    with redirect_stdout(io.StringIO()) as output, redirect_stderr(output):
        code = _run(rosdep, ['update'])
    if code != 0:
        print(output.getvalue(), end='', file=sys.stderr)
        raise SystemExit(code)
    stamp.write_text(current)


def _install_without_apt(rosdep, argv: list[str]) -> int:
    """rosdep install, with every system installer replaced by one line per package."""
    from rosdep2.platforms import debian

    refused: list[str] = []
    simulate = '-s' in argv or '--simulate' in argv

    def name_instead(self, resolved, interactive=True, reinstall=False, quiet=False):
        for package in self.get_packages_to_install(resolved, reinstall=reinstall):
            if package not in refused:
                refused.append(package)
                print(f'rosdep: {package} is a system package, which this workspace\'s rosdep '
                      f'does not install: run `sudo apt-get install {package}`')
        return []

    if simulate:
        return _run(rosdep, argv)
    debian.AptInstaller.get_install_command = name_instead
    if not ({'-y', '--default-yes'} & set(argv)):
        code = _run(rosdep, argv)  # interactive: rosdep's prompts must reach the terminal
        return code if code else (1 if refused else 0)
    with redirect_stdout(io.StringIO()) as said:
        code = _run(rosdep, argv)
    for line in said.getvalue().splitlines():
        if not (refused and line == '#All required rosdeps installed successfully'):
            print(line)
    if refused and not code:
        print(f'rosdep: {len(refused)} system package(s) left for you to install (above); '
              'everything else is installed')
    return code if code else (1 if refused else 0)


if __name__ == '__main__':
    sys.exit(main())
