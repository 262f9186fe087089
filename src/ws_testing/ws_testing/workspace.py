"""A colcon workspace a test makes as a tutorial page does: `ros2 pkg create` in its src/,
the page's edits, `colcon build`; every command on a leased domain of its own."""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

import pytest

from ws_testing.support import leased_domain, ros_environment, run_checked


@dataclass
class ColconWorkspace:
    root: Path
    env: dict[str, str]

    @property
    def src(self) -> Path:
        return self.root / 'src'

    def create(self, name: str, *options: str) -> Path:
        """`ros2 pkg create NAME OPTIONS...` in src/ (the name first: `--dependencies` takes
        every word after it); the new package's folder."""
        run_checked(['ros2', 'pkg', 'create', name, *options], self.src, self.env)
        return self.src / name

    def build(self, *args: str, timeout: float = 400.0) -> None:
        """`colcon build ARGS...` in the workspace; fails the test with colcon's output."""
        run_checked(['colcon', 'build', *args], self.root, self.env, timeout=timeout)


@contextmanager
def colcon_workspace(tmp_path_factory: pytest.TempPathFactory, name: str = 'ros2_ws'
                     ) -> Iterator[ColconWorkspace]:
    """A fresh `<tmp>/<name>/src`, with the environment of a domain leased for the block."""
    root = tmp_path_factory.mktemp(name)
    (root / 'src').mkdir()
    with leased_domain() as domain:
        yield ColconWorkspace(root, ros_environment(domain))
