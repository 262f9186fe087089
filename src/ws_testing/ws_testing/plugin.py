"""Fixtures shared by every test: a leased ROS domain, node processes, an rclpy probe."""

from __future__ import annotations

import os
import signal
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest

from support import (
    LEASED_DOMAINS,
    OWNER_VARIABLE,
    RosProcess,
    TestNode,
    executable,
    leased_domain,
    owner_token,
    ros_environment,
    stop_daemon,
    stop_leftovers,
)

if not os.environ.get('_ROS_WHEELS_BOOTSTRAP_COMPLETE'):
    pytest.exit('run the tests through scripts/test (it sources the workspace)', returncode=4)

# A shell without job control starts `scripts/test &` with SIGINT and SIGQUIT ignored, and
# every process a test starts would inherit that: a node Ctrl-C'd while it starts would never
# hear it (seen: the clean-exit tests failed in such a run). The tests are about Ctrl-C, so
# the session takes Python's default back; exec resets it to the default in the children.
for _signum, _default in ((signal.SIGINT, signal.default_int_handler),
                          (signal.SIGQUIT, signal.SIG_DFL)):
    if signal.getsignal(_signum) == signal.SIG_IGN:
        signal.signal(_signum, _default)


# Whose processes are these? Each process inherits OWNER_VARIABLE (tests/support.py) from the
# code that started it: a fixture's setup marks them with the fixture's scope (the test, its
# module, the session), also when a test asks for a module fixture late (getfixturevalue); the
# test's own body with the test. Processes started with a module's environment (module_ros_env)
# belong to the module. At the end of each scope, what still runs of it is a leak.
@pytest.hookimpl(hookwrapper=True)
def pytest_fixture_setup(fixturedef: pytest.FixtureDef, request: pytest.FixtureRequest
                         ) -> Iterator[None]:
    os.environ[OWNER_VARIABLE] = owner_token(request.node.nodeid)
    yield


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_call(item: pytest.Item) -> Iterator[None]:
    os.environ[OWNER_VARIABLE] = owner_token(item.nodeid)
    yield


def _fail_on_leftovers(scope: str, matches: Callable[[str], bool]) -> None:
    """After a scope's own fixtures stopped what they started: fail naming what still runs."""
    left = stop_leftovers(matches)
    if left:
        pytest.fail(f'{scope} left processes running (killed now):\n' + '\n'.join(left),
                    pytrace=False)


@pytest.fixture(scope='session', autouse=True)
def no_daemon_left() -> Iterator[None]:
    """Whatever test started a `ros2` daemon on a leased domain, none outlives the session;
    nor does any other process the session started."""
    yield
    for leased in sorted(LEASED_DOMAINS):
        stop_daemon(ros_environment(leased))
    os.environ.pop(OWNER_VARIABLE, None)
    session = owner_token('')
    _fail_on_leftovers('the test session', lambda owner: owner.startswith(session))


@pytest.fixture(scope='module', autouse=True)
def no_process_left_by_module(request: pytest.FixtureRequest) -> Iterator[None]:
    """Processes of a module's shared fixtures (module_launch, a module's own) are its own."""
    yield
    token = owner_token(request.node.nodeid)
    _fail_on_leftovers(f'module {request.node.nodeid}', lambda owner: owner == token)


@pytest.fixture(autouse=True)
def no_process_left_by_test(request: pytest.FixtureRequest) -> Iterator[None]:
    """A test fails when a process it started, or a descendant of one, outlives it."""
    yield
    token = owner_token(request.node.nodeid)
    _fail_on_leftovers(request.node.nodeid, lambda owner: owner == token)


@pytest.fixture
def domain() -> Iterator[int]:
    with leased_domain() as leased:
        yield leased


@pytest.fixture
def ros_env(domain: int) -> Iterator[dict[str, str]]:
    env = ros_environment(domain)
    yield env
    stop_daemon(env)  # graph verbs start a daemon for the test's domain: leave none behind


@contextmanager
def _launcher(ros_env: dict[str, str], directory: Path) -> Iterator[Callable[..., RosProcess]]:
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
    node = TestNode(domain)
    yield node
    node.close()
