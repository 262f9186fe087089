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
        return {run: _RunnerWorker(run, self._launch_file_arguments, self._debug).run()
                for run in self._test_runs}


class _RunnerWorker:
    """One launch of a test run: the launch on this thread, the active tests (`_run_test`)
    on a second one, then the post-shutdown tests."""

    def __init__(self, test_run: TestRun, launch_file_arguments: list[str],
                 debug: bool) -> None:
        self._test_run = test_run
        self._arguments = [tuple(argument.split(':=', 1))
                           for argument in launch_file_arguments]
        self._result = TestResult()
        self._ready = threading.Event()
        self._tests_done = threading.Event()
        self._proc_info = ActiveProcInfoHandler()
        self._proc_output = ActiveIoHandler()
        self._service = LaunchService(argv=launch_file_arguments, debug=debug)
        self._injected: dict[str, Any] = {}

    def run(self) -> TestResult:
        test_run, result = self._test_run, self._result
        proc_info, proc_output = self._proc_info, self._proc_output
        description, extra_context = test_run.normalized_test_description(
            ready_fn=self._ready.set)

        def on_start(event: Any, _context: Any) -> None:
            proc_info.append(event)
            proc_output.track(event.process_name, event.action)

        self._service.include_launch_description(LaunchDescription([
            RegisterEventHandler(OnProcessStart(on_start=on_start)),
            RegisterEventHandler(OnProcessIO(on_stdout=proc_output.append,
                                             on_stderr=proc_output.append)),
            RegisterEventHandler(OnProcessExit(
                on_exit=lambda event, _context: proc_info.append(event))),
            IncludeLaunchDescription(LaunchDescriptionSource(description),
                                     launch_arguments=self._arguments),
        ]))
        # As upstream: test_args are the launch arguments; the parameters of a parametrized
        # description are injected by their own names, next to its test context.
        self._injected = {'proc_info': proc_info, 'proc_output': proc_output,
                          'test_args': dict(self._arguments), 'launch_service': self._service,
                          **extra_context, **test_run.param_args}
        active = threading.Thread(target=self._run_test, name='launch_testing active tests',
                                  daemon=True)
        keep_alive = bool(test_run.markers.get('keep_alive'))
        started = time.monotonic()
        active.start()
        launch_code = self._service.run(shutdown_when_idle=not keep_alive)
        # The last process may end while a test is still returning from its wait for that:
        # give the active tests a moment before calling the launch's end premature.
        active.join(timeout=LAUNCH_ENDED_GRACE)
        if not self._tests_done.is_set():
            # Every process ended (or Ctrl-C) and the active tests still wait, for output
            # that can no longer come: say which processes failed, with what they wrote.
            result.add_run_error('Launch stopped before the active tests finished: '
                                 + _summary(proc_info))
            _print_failed_processes(proc_info, proc_output)
        if launch_code != 0:
            result.add_run_error(f'the launch failed (exit code {launch_code}); see its log above')
        if self._ready.is_set() and self._tests_done.is_set():
            final = {**self._injected, 'proc_info': proc_info._proc_info_handler,
                     'proc_output': proc_output._io_handler}
            test_run.bind(test_run.post_shutdown_tests, final, final)
            _run_suite(test_run.post_shutdown_tests, result)
        result.duration = time.monotonic() - started
        return result

    def _run_test(self) -> None:
        """The active tests, once ReadyToTest ran; then the launch is asked to stop."""
        test_run = self._test_run
        try:
            if not self._ready.wait(test_run.timeout):
                self._result.add_run_error(
                    f'Timed out waiting for ReadyToTest ({test_run.timeout:g} s): the launch '
                    'did not reach the ReadyToTest action')
                return
            test_run.bind(test_run.pre_shutdown_tests, self._injected, self._injected)
            _run_suite(test_run.pre_shutdown_tests, self._result)
        finally:
            self._tests_done.set()
            _shutdown_soon(self._service)


def _print_failed_processes(proc_info: ActiveProcInfoHandler,
                            proc_output: ActiveIoHandler) -> None:
    """Each process that exited with an error code, and its output (upstream prints them)."""
    failed = [info for info in proc_info if getattr(info, 'returncode', 0)]
    if not failed:
        return
    print('\nProcesses under test stopped before tests completed')
    for info in failed:
        print(f'\n{info.process_name} exited with code {info.returncode}')
        try:
            events = proc_output[info.action]
        except KeyError:
            events = []
        text = ''.join(event.text.decode(errors='replace') for event in events)
        print(text.rstrip('\n') if text else '(no output)')


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
