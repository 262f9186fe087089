"""The workspace's pytest plugin (entry point pytest11 `ws_testing`): the fixtures every test
uses: a leased ROS domain, node processes, an rclpy probe.

Loaded by every pytest run where ws_testing is installed, as launch_testing's plugin is, so
the tests of any package find these fixtures under `scripts/test` and under `colcon test`.
Only fixtures a test asks for run; what acts on every test (the leak check of
ws_testing.leak_check, Ctrl-C restored for the processes a test starts) is switched on by the
ini option `ws_testing_checks = true` (the workspace's pyproject.toml), so pytest runs of
other projects in the same environment (a `colcon test` of a package a test creates) stay as
they were.
"""

from __future__ import annotations

import os
import signal
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING

import pytest

if TYPE_CHECKING:
    from ws_testing.support import RosProcess, TestNode


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addini('ws_testing_checks', type='bool', default=False,
                  help='ws_testing: fail a test that leaves a process running, restore Ctrl-C '
                       'for the processes tests start, and require a sourced ROS environment')


def pytest_configure(config: pytest.Config) -> None:
    if not config.getini('ws_testing_checks'):
        return
    sourced = ('_ROS_WHEELS_BOOTSTRAP_COMPLETE', 'AMENT_PREFIX_PATH')  # ours, or apt's setup
    if not any(os.environ.get(name) for name in sourced):
        pytest.exit('run the tests through scripts/test (it sources the workspace), or source '
                    'a ROS 2 environment first', returncode=4)
    # A shell without job control starts `scripts/test &` with SIGINT and SIGQUIT ignored, and
    # every process a test starts would inherit that: a node Ctrl-C'd while it starts would
    # never hear it (seen: the clean-exit tests failed in such a run). The tests are about
    # Ctrl-C, so the session takes Python's default back; exec resets it in the children.
    for signum, default in ((signal.SIGINT, signal.default_int_handler),
                            (signal.SIGQUIT, signal.SIG_DFL)):
        if signal.getsignal(signum) == signal.SIG_IGN:
            signal.signal(signum, default)
    from ws_testing import leak_check
    if not config.pluginmanager.is_registered(leak_check):
        config.pluginmanager.register(leak_check, 'ws_testing.leak_check')


@pytest.fixture
def domain() -> Iterator[int]:
    from ws_testing.support import leased_domain
    with leased_domain() as leased:
        yield leased


@pytest.fixture
def ros_env(domain: int) -> Iterator[dict[str, str]]:
    from ws_testing.support import ros_environment, stop_daemon
    env = ros_environment(domain)
    yield env
    stop_daemon(env)  # graph verbs start a daemon for the test's domain: leave none behind


@contextmanager
def _launcher(ros_env: dict[str, str], directory: Path) -> Iterator[Callable[..., RosProcess]]:
    from ws_testing.support import RosProcess, executable
    started: list[RosProcess] = []

    def start(package: str | None = None, name: str | None = None, *args: str,
              argv: list[str] | None = None, env: dict[str, str] | None = None) -> RosProcess:
        command = argv if argv is not None else [executable(package, name), *args]
        log = directory / f'{len(started):02d}-{Path(command[0]).name}.log'
        process = RosProcess(command, env or ros_env, log)
        started.append(process)
        return process

    yield start
    for process in reversed(started):
        process.stop()


@pytest.fixture
def launch(ros_env: dict[str, str], tmp_path: Path) -> Iterator[Callable[..., RosProcess]]:
    """launch('pkg', 'exe', *args) or launch(argv=[...]) starts a process; all stop at teardown."""
    with _launcher(ros_env, tmp_path) as start:
        yield start


@pytest.fixture(scope='module')
def module_ros_env() -> Iterator[dict[str, str]]:
    """A domain and environment shared by the tests of one module (one turtlesim for all)."""
    from ws_testing.support import leased_domain, ros_environment, stop_daemon
    with leased_domain() as leased:
        env = ros_environment(leased)
        yield env
        stop_daemon(env)  # as ros_env: leave no daemon behind


@pytest.fixture(scope='module')
def module_launch(module_ros_env: dict[str, str], tmp_path_factory: pytest.TempPathFactory
                  ) -> Iterator[Callable[..., RosProcess]]:
    """Like launch, in module_ros_env; the processes stop after the module's last test."""
    with _launcher(module_ros_env, tmp_path_factory.mktemp('module_launch')) as start:
        yield start


@pytest.fixture(scope='module')
def module_turtlesim(module_launch: Callable[..., RosProcess]) -> RosProcess:
    """A headless turtlesim_node in module_ros_env, up to its first turtle."""
    process = module_launch('turtlesim', 'turtlesim_node', '--headless')
    process.wait_for_output(r'Spawning turtle \[turtle1\]')
    return process


@pytest.fixture
def probe(domain: int) -> Iterator[TestNode]:
    from ws_testing.support import TestNode
    node = TestNode(domain)
    yield node
    node.close()
