"""Collect launch test files (a module with generate_test_description) as one item each.

Registered as a pytest11 entry point, as upstream's: once launch_testing is installed,
`pytest` and `colcon test` run launch tests next to plain ones. A failure shows each failing
test's traceback, with the file and line of the failing assertion.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import pytest

_DEFINES_DESCRIPTION = re.compile(r'^def generate_test_description\(', re.MULTILINE)


class LaunchTestFailure(Exception):
    def __init__(self, report: str) -> None:
        super().__init__(report)
        self.report = report


class LaunchTestItem(pytest.Item):
    def runtest(self) -> None:
        from launch_testing.launch_test import load_module, report
        from launch_testing.loader import LoadTestsFromPythonModule
        from launch_testing.test_runner import LaunchTestRunner

        module = load_module(Path(self.path))
        runs = LoadTestsFromPythonModule(module, name=Path(self.path).stem)
        # --launch-args may be given several times, each with several name:=value words.
        launch_args = [word for words in self.config.getoption('--launch-args') or []
                       for word in words]
        runner = LaunchTestRunner(runs, launch_file_arguments=launch_args)
        runner.validate()
        results = runner.run()
        if not all(result.wasSuccessful() for result in results.values()):
            import io
            text = io.StringIO()
            # What failed first (colcon test-result shows only a report's first lines), then
            # unittest's full report with the tracebacks.
            for result in results.values():
                for case in result.cases:
                    if case.outcome in ('failure', 'error'):
                        where = f' at {case.where}' if case.where else ''
                        print(f'{case.outcome.upper()}: {case.name} ({case.classname}){where}: '
                              f'{case.message}', file=text)
            print(file=text)
            report(results, text)
            raise LaunchTestFailure(text.getvalue())

    def repr_failure(self, excinfo: Any, style: Any = None) -> str:
        if isinstance(excinfo.value, LaunchTestFailure):
            return excinfo.value.report
        return super().repr_failure(excinfo)

    def reportinfo(self) -> tuple[Path, int, str]:
        return Path(self.path), 0, f'launch tests: {self.name}'


class LaunchTestModule(pytest.File):
    def collect(self) -> Any:
        yield LaunchTestItem.from_parent(self, name=Path(self.path).stem)


def pytest_addoption(parser: Any) -> None:
    parser.addoption('--launch-args', action='append', nargs='*', default=[],
                     help='name:=value arguments for the launch descriptions of launch tests')


def pytest_configure(config: Any) -> None:
    # Launch test files mark generate_test_description with it: known even with
    # --strict-markers, as upstream's plugin declares it.
    config.addinivalue_line('markers', 'launch_test: the test description of a launch test')


def pytest_pycollect_makemodule(module_path: Path, parent: Any) -> Any:
    """A test file that defines generate_test_description is a launch test."""
    try:
        source = Path(module_path).read_text(errors='replace')
    except OSError:
        return None
    if _DEFINES_DESCRIPTION.search(source) is None:
        return None
    return LaunchTestModule.from_parent(parent, path=Path(module_path))
