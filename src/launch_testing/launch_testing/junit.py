"""Write launch test results as JUnit XML, the format colcon test-result reads."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

from launch_testing.loader import TestRun
from launch_testing.test_result import TestResult


def write(results: dict[TestRun, TestResult], path: Path, suite_name: str,
          package: str | None = None) -> None:
    suites = ET.Element('testsuites')
    for run, result in results.items():
        cases = result.cases
        suite = ET.SubElement(suites, 'testsuite', {
            'name': suite_name if len(results) == 1 else f'{suite_name}[{run}]',
            'tests': str(len(cases)),
            'failures': str(sum(case.outcome == 'failure' for case in cases)),
            'errors': str(sum(case.outcome == 'error' for case in cases)),
            'skipped': str(sum(case.outcome == 'skipped' for case in cases)),
            'time': f'{result.duration:.3f}'})
        for case in cases:
            element = ET.SubElement(suite, 'testcase', {
                'classname': f'{package}.{case.classname}' if package else case.classname,
                'name': case.name,
                'time': f'{case.seconds:.3f}'})
            if case.outcome != 'passed':
                detail = ET.SubElement(element, case.outcome, {'message': case.message})
                detail.text = case.details
    path.parent.mkdir(parents=True, exist_ok=True)
    ET.ElementTree(suites).write(path, encoding='utf-8', xml_declaration=True)
