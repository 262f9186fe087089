"""Launch test results as JUnit XML, the format colcon test-result reads (upstream's
`unittestResultsToXml`)."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Mapping
from pathlib import Path

from launch_testing.test_result import TestResult

_COUNTS = ('failure', 'error', 'skipped')


def _suite(name: str, result: TestResult) -> ET.Element:
    cases = result.cases
    counts = {kind: str(sum(case.outcome == kind for case in cases)) for kind in _COUNTS}
    suite = ET.Element('testsuite', {
        'name': name, 'tests': str(len(cases)), 'failures': counts['failure'],
        'errors': counts['error'], 'skipped': counts['skipped'],
        'time': f'{result.duration:.3f}'})
    for case in cases:
        element = ET.SubElement(suite, 'testcase', {
            'classname': case.classname, 'name': case.name, 'time': f'{case.seconds:.3f}'})
        if case.outcome != 'passed':
            # The message is unittest's whole report of the test (upstream's), which holds
            # the failing line even for a bare `assert`.
            detail = ET.SubElement(element, case.outcome,
                                   {'message': case.details or case.message})
            detail.text = case.details
    return suite


def unittestResultsToXml(*, name: str = 'launch_test',
                         test_results: Mapping[str, TestResult]) -> ET.ElementTree:
    """A <testsuites> tree with one <testsuite> per named result."""
    root = ET.Element('testsuites', {'name': name})
    totals = dict.fromkeys(('tests', 'failures', 'errors', 'skipped'), 0)
    for suite_name, result in test_results.items():
        suite = _suite(suite_name, result)
        root.append(suite)
        for key in totals:
            totals[key] += int(suite.get(key, '0'))
    for key, value in totals.items():
        root.set(key, str(value))
    return ET.ElementTree(root)


def write(results: Mapping[str, TestResult], path: Path) -> None:
    tree = unittestResultsToXml(test_results=results)
    path.parent.mkdir(parents=True, exist_ok=True)
    tree.write(path, encoding='utf-8', xml_declaration=True)
