"""ros2 doctor [--report | --report-failed] [--exclude-packages] [--include-warnings]

Also registered as `ros2 wtf`, as in ros2cli.
"""

from __future__ import annotations

import argparse

from ros2cli.verb_context import VerbContext


def add_arguments(parser: argparse.ArgumentParser) -> None:
    group = parser.add_mutually_exclusive_group(required=False)
    group.add_argument('--report', '-r', action='store_true', help='Print all reports.')
    group.add_argument('--report-failed', '-rf', action='store_true',
                       help='Print reports of failed checks only.')
    parser.add_argument('--exclude-packages', '-ep', action='store_true',
                        help='Exclude package checks or report.')
    parser.add_argument('--include-warnings', '-iw', action='store_true',
                        help='Include warnings as failed checks. Warnings are ignored by '
                        'default.')
    parser.set_defaults(_main=main)


def _print_reports(makers, categories: list[str] | None, context: VerbContext) -> None:
    from ros2doctor.api import Result, print_report
    for category, make in makers:
        if categories is not None and category not in categories:
            continue
        try:
            reports = make()
        except Exception as error:  # e.g. rcl refused the environment: say so, go on
            Result().fail(f'Unable to report {category}: {" ".join(str(error).split())}')
            continue
        for report in reports:
            print_report(report, context.stdout)


def main(args: argparse.Namespace, context: VerbContext) -> int:
    from ros2doctor.api.checks import CHECKS, REPORTS

    def wanted(category: str) -> bool:
        return not (args.exclude_packages and category == 'package')

    if args.report:
        _print_reports(REPORTS, [c for c, _ in REPORTS if wanted(c)], context)
        return 0

    failed: list[str] = []
    total = fails = 0
    for category, check in CHECKS:
        if not wanted(category):
            continue
        result = check()
        total += 1
        if result.error or (args.include_warnings and result.warning):
            fails += 1
            if category not in failed:
                failed.append(category)
    if fails:
        print(f'\n{fails}/{total} check(s) failed\n', file=context.stdout)
        print('Failed modules:', *failed, file=context.stdout)
    else:
        print(f'\nAll {total} checks passed\n', file=context.stdout)
    if args.report_failed and fails:
        _print_reports(REPORTS, failed, context)
    return 0
