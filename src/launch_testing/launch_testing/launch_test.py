"""`launch_test FILE [name:=value ...]`: run a launch test file, as upstream's command.

Prints each test as unittest does, a summary per launch, and returns 0 only if every test
of every launch passed. `--junit-xml FILE` also writes the results for colcon test-result.
"""

from __future__ import annotations

import argparse
import importlib.util
import sys
import unittest
from pathlib import Path
from types import ModuleType
from typing import Any

from launch_testing import junitxml
from launch_testing.loader import LoadTestsFromPythonModule, TestRun
from launch_testing.test_result import TestResult
from launch_testing.test_runner import LaunchTestRunner


def load_module(path: Path) -> ModuleType:
    """Import a launch test file under its own name (its directory first on sys.path)."""
    spec = importlib.util.spec_from_file_location(path.stem, path)
    if spec is None or spec.loader is None:
        raise ImportError(f'cannot import {path}')
    module = importlib.util.module_from_spec(spec)
    sys.path.insert(0, str(path.parent))
    try:
        spec.loader.exec_module(module)
    finally:
        sys.path.remove(str(path.parent))
    if not hasattr(module, 'generate_test_description'):
        raise ImportError(f'{path} has no generate_test_description function: not a launch test')
    return module


def print_arguments(description: Any) -> None:
    """The launch arguments a test description declares, as `launch_test --show-args` lists
    them (upstream's format)."""
    arguments = description.get_launch_arguments()
    if not arguments:
        print('No arguments.')
        return
    print("Arguments (pass arguments as '<name>:=<value>'):")
    for argument in arguments:
        print(f"\n    '{argument.name}':\n        {argument.description}")


def report(results: dict[TestRun, TestResult], stream) -> None:
    """unittest's text report: one line per test, the failures, then 'Ran N tests'."""
    for run, result in results.items():
        for case in result.cases:
            verdict = {'passed': 'ok', 'failure': 'FAIL', 'error': 'ERROR',
                       'skipped': 'skipped'}[case.outcome]
            print(f'{case.name} ({case.classname}) ... {verdict}', file=stream)
        text = unittest.TextTestResult(unittest.runner._WritelnDecorator(stream),
                                       descriptions=False, verbosity=1)
        text.failures, text.errors = result.failures, result.errors
        text.printErrors()
        print(f'{"-" * 70}\nRan {result.testsRun} tests in {result.duration:.3f}s\n', file=stream)
        print('OK' if result.wasSuccessful() else
              f'FAILED (failures={len(result.failures)}, errors={len(result.errors)})',
              file=stream)
        if len(results) > 1:
            print(f'({run})', file=stream)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog='launch_test',
                                     description='Launch integration testing tool.')
    parser.add_argument('-v', '--verbose', action='store_true',
                        help='Run with verbose output')
    parser.add_argument('-s', '--show-args', '--show-arguments', action='store_true',
                        help='Show arguments that may be given to the launch test.')
    parser.add_argument('--junit-xml', type=Path,
                        help='write xml output to the specified file rather than print it')
    parser.add_argument('--package-name', default=None,
                        help='a name for the test suite in the xml (default: the file name)')
    parser.add_argument('launch_test_file', type=Path, help='Path to the launch test.')
    parser.add_argument('launch_args', nargs='*', help='Arguments to the launch file; '
                        "'<name>:=<value>' (for duplicates, last one wins)")
    args = parser.parse_args(argv)
    if not args.launch_test_file.is_file():
        parser.error(f"launch test file '{args.launch_test_file}' does not exist")
    module = load_module(args.launch_test_file.resolve())
    # As upstream: runs named '<package>.<file>.launch_tests', the XML's test suite names.
    package = args.package_name or args.launch_test_file.stem
    runs = LoadTestsFromPythonModule(
        module, name=f'{package}.{args.launch_test_file.stem}.launch_tests')
    if args.show_args:
        for run in runs:
            print_arguments(run.get_launch_description())
        return 0
    runner = LaunchTestRunner(runs, launch_file_arguments=args.launch_args,
                              debug=args.verbose)
    try:
        runner.validate()
    except ValueError as error:
        parser.error(str(error))
    results = runner.run()
    report(results, sys.stderr)
    if args.junit_xml is not None:
        junitxml.write({str(run): result for run, result in results.items()}, args.junit_xml)
    return 0 if all(result.wasSuccessful() for result in results.values()) else 1


if __name__ == '__main__':
    sys.exit(main())
