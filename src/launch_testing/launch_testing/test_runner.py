"""LaunchTestRunner: launch a test description, run its tests, collect the results.

The launch runs on the calling (main) thread, as launch needs for its signal handling; the
active tests run on a second thread once ReadyToTest executed, then ask the launch to shut
down. Post-shutdown tests run after the launch ended, with every exit code known.
"""

from __future__ import annotations

import inspect
import threading
import time
import unittest
from collections.abc import Iterable
from typing import Any

from launch.actions import IncludeLaunchDescription, RegisterEventHandler
from launch.event_handlers import OnProcessExit, OnProcessIO, OnProcessStart
from launch.launch_description_sources import LaunchDescriptionSource

from launch import LaunchDescription, LaunchService
from launch_testing.io_handler import ActiveIoHandler
from launch_testing.loader import TestRun
from launch_testing.proc_info_handler import ActiveProcInfoHandler
from launch_testing.test_result import TestResult

LAUNCH_ENDED_GRACE = 5.0  # seconds the active tests get to finish once the launch ended


class LaunchTestRunner:
    def __init__(self, test_runs: list[TestRun], launch_file_arguments: Iterable[str] = (),
                 debug: bool = False) -> None:
        self._test_runs = test_runs
        self._launch_file_arguments = list(launch_file_arguments)
        self._debug = debug

    def validate(self) -> None:
        """Refuse malformed launch arguments, and test descriptions whose parameters are
        neither `ready_fn` nor the ones @launch_testing.parametrize gives."""
        for argument in self._launch_file_arguments:
            if ':=' not in argument:
                raise ValueError(f"launch argument '{argument}' is not of the form name:=value")
        for run in self._test_runs:
            function = run._test_description_function
            function = getattr(function, 'func', function)  # parametrize binds with a partial
            parameters = set(inspect.signature(function).parameters)
            for name in sorted(parameters - {'ready_fn'} - set(run.param_args)):
                raise Exception(f"generate_test_description has unexpected extra argument "
                                f"'{name}'")
            for name in sorted(set(run.param_args) - parameters):
                raise Exception('Could not find an argument in generate_test_description '
                                f"matching parametrized argument '{name}'")

    def run(self) -> dict[TestRun, TestResult]:
        return {run: self._run_test(run) for run in self._test_runs}

    def _arguments(self) -> list[tuple[str, str]]:
        return [tuple(argument.split(':=', 1)) for argument in self._launch_file_arguments]

    def _run_test(self, test_run: TestRun) -> TestResult:
        result = TestResult()
        ready = threading.Event()
        tests_done = threading.Event()
        description, extra_context = test_run.normalized_test_description(ready_fn=ready.set)
        proc_info = ActiveProcInfoHandler()
        proc_output = ActiveIoHandler()

        def on_start(event: Any, _context: Any) -> None:
            proc_info.append(event)
            proc_output.track(event.process_name, event.action)

        service = LaunchService(argv=self._launch_file_arguments, debug=self._debug)
        service.include_launch_description(LaunchDescription([
            RegisterEventHandler(OnProcessStart(on_start=on_start)),
            RegisterEventHandler(OnProcessIO(on_stdout=proc_output.append,
                                             on_stderr=proc_output.append)),
            RegisterEventHandler(OnProcessExit(
                on_exit=lambda event, _context: proc_info.append(event))),
            IncludeLaunchDescription(LaunchDescriptionSource(description),
                                     launch_arguments=self._arguments()),
        ]))
        # As upstream: test_args are the launch arguments; the parameters of a parametrized
        # description are injected by their own names, next to its test context.
        injected = {'proc_info': proc_info, 'proc_output': proc_output,
                    'test_args': dict(self._arguments()), 'launch_service': service,
                    **extra_context, **test_run.param_args}

        def run_active_tests() -> None:
            try:
                if not ready.wait(test_run.timeout):
                    result.add_run_error(
                        f'Timed out waiting for ReadyToTest ({test_run.timeout:g} s): the '
                        'launch did not reach the ReadyToTest action')
                    return
                test_run.bind(test_run.pre_shutdown_tests, injected, injected)
                _run_suite(test_run.pre_shutdown_tests, result)
            finally:
                tests_done.set()
                _shutdown_soon(service)

        active = threading.Thread(target=run_active_tests, name='launch_testing active tests',
                                  daemon=True)
        keep_alive = bool(test_run.markers.get('keep_alive'))
        started = time.monotonic()
        active.start()
        launch_code = service.run(shutdown_when_idle=not keep_alive)
        # The last process may end while a test is still returning from its wait for that:
        # give the active tests a moment before calling the launch's end premature.
        active.join(timeout=LAUNCH_ENDED_GRACE)
        if not tests_done.is_set():
            # Every process ended (or Ctrl-C) and the active tests still wait, for output
            # that can no longer come.
            result.add_run_error('Launch stopped before the active tests finished: '
                                 + _summary(proc_info))
        if launch_code != 0:
            result.add_run_error(f'the launch failed (exit code {launch_code}); see its log above')
        if ready.is_set() and tests_done.is_set():
            final = {**injected, 'proc_info': proc_info._proc_info_handler,
                     'proc_output': proc_output._io_handler}
            test_run.bind(test_run.post_shutdown_tests, final, final)
            _run_suite(test_run.post_shutdown_tests, result)
        result.duration = time.monotonic() - started
        return result


def _run_suite(suite: unittest.TestSuite, result: TestResult) -> None:
    """Run a suite into a result that earlier suites used too.

    unittest remembers on the result the class of the last test it ran, and tears that class
    down when the next test's class differs, even in a later suite: then the active tests'
    tearDownClass would run a second time when the post-shutdown tests start. Forget it.
    """
    result._previousTestClass = None  # type: ignore[attr-defined]
    suite.run(result)


def _shutdown_soon(service: LaunchService) -> None:
    """Ask the launch to stop, from the tests' thread (launch is not thread-safe)."""
    loop = getattr(service.context, '_loop', None)
    if loop is not None and not loop.is_closed():
        try:
            loop.call_soon_threadsafe(service.shutdown, 'the active tests finished')
        except RuntimeError:
            pass  # the loop already stopped: the launch is over


def _summary(proc_info: ActiveProcInfoHandler) -> str:
    exits = [f'{info.process_name} exited with code {info.returncode}'
             for info in proc_info if getattr(info, 'returncode', None) is not None]
    return '; '.join(exits) or 'no process was started'


def results_ok(results: dict[TestRun, unittest.TestResult]) -> bool:
    return all(result.wasSuccessful() for result in results.values())
