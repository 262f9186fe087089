"""No test leaves a process behind: registered by ws_testing.plugin when the ini option
ws_testing_checks is on (the workspace's pyproject.toml).

Whose processes are these? Each process inherits OWNER_VARIABLE (ws_testing.support) from the
code that started it: a fixture's setup marks them with the fixture's scope (the test, its
module, the session), also when a test asks for a module fixture late (getfixturevalue); the
test's own body with the test. Processes started with a module's environment (module_ros_env)
belong to the module. At the end of each scope, what still runs of it is a leak.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator

import pytest

from ws_testing.support import (
    LEASED_DOMAINS,
    OWNER_VARIABLE,
    owner_token,
    ros_environment,
    stop_daemon,
    stop_leftovers,
)


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
