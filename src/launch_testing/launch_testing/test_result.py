"""TestResult: unittest's result with each test's duration and the launch's own errors,
enough for a text summary and a JUnit XML file (what colcon test-result reads)."""

from __future__ import annotations

import re
import time
import unittest
from dataclasses import dataclass
from typing import Any


@dataclass
class CaseResult:
    classname: str
    name: str
    seconds: float
    outcome: str = 'passed'  # passed, failure, error, skipped
    message: str = ''
    details: str = ''

    @property
    def where(self) -> str:
        """'file:line' of the innermost frame of the failure's traceback, or ''."""
        frames = _FRAME.findall(self.details)
        return f'{frames[-1][0]}:{frames[-1][1]}' if frames else ''


class TestResult(unittest.TestResult):
    def __init__(self, stream: Any = None, descriptions: Any = None,
                 verbosity: Any = None) -> None:
        # unittest.TextTestRunner makes its results with these arguments.
        super().__init__(stream, descriptions, verbosity)
        self.cases: list[CaseResult] = []
        self.duration = 0.0
        self._started: dict[str, float] = {}

    def startTest(self, test: unittest.TestCase) -> None:
        super().startTest(test)
        self._started[test.id()] = time.monotonic()

    def stopTest(self, test: unittest.TestCase) -> None:
        super().stopTest(test)
        seconds = time.monotonic() - self._started.pop(test.id(), time.monotonic())
        classname, _, name = test.id().rpartition('.')
        outcome, message, details = 'passed', '', ''
        for kind, found in (('failure', self.failures), ('error', self.errors),
                            ('skipped', self.skipped)):
            for case, text in found:
                if case is test:
                    outcome, details = kind, text
                    message = _exception_line(text) or kind
        self.cases.append(CaseResult(classname, name, seconds, outcome, message, details))

    def add_run_error(self, message: str) -> None:
        """An error of the launch itself (no ReadyToTest, processes gone early)."""
        self.errors.append((_RunProblem(message), message))
        self.cases.append(CaseResult('launch_testing', 'launch', 0.0, 'error', message, message))


class FailResult(TestResult):
    """Every test of a run failed with one message (the launch itself failed)."""

    def __init__(self, test_run: Any, message: str) -> None:
        super().__init__()
        for case in test_run.all_cases():
            classname, _, name = case.id().rpartition('.')
            self.failures.append((case, message))
            self.cases.append(CaseResult(classname, name, 0.0, 'failure', message, message))


class SkipResult(TestResult):
    """Every test of a run skipped, with the reason."""

    def __init__(self, test_run: Any, skip_reason: str) -> None:
        super().__init__()
        for case in test_run.all_cases():
            classname, _, name = case.id().rpartition('.')
            self.skipped.append((case, skip_reason))
            self.cases.append(CaseResult(classname, name, 0.0, 'skipped', skip_reason, ''))


def _exception_line(traceback_text: str) -> str:
    """The 'AssertionError: ...' line of a traceback (its message's first line)."""
    for line in traceback_text.splitlines():
        if _EXCEPTION_LINE.match(line):
            return line
    lines = traceback_text.strip().splitlines()
    return lines[-1] if lines else ''


_FRAME = re.compile(r'File "([^"]+)", line (\d+)')
_EXCEPTION_LINE = re.compile(r'^[A-Za-z_][\w.]*(Error|Exception|Failure|Exit)\b.*')


class _RunProblem(unittest.TestCase):
    def __init__(self, message: str) -> None:
        super().__init__()
        self._message = message

    def runTest(self) -> None:
        """Stands for the launch in unittest's error list."""

    def id(self) -> str:
        return 'launch_testing.launch'

    def __str__(self) -> str:
        return 'launch (launch_testing)'
