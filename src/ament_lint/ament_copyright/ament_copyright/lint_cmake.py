"""ament_lint_cmake: CMake style via cmakelint (PyPI), with ament_lint_cmake's defaults.

ament_lint's own package vendors cmakelint; here the PyPI release (pinned in the lock) does the
checking, with upstream's 140-column line length and no user rc file.
"""

from __future__ import annotations

import argparse
import os
import sys
import time

from ament_copyright._lint import find_files, write_xunit


def _is_cmake(name: str) -> bool:
    return name == 'CMakeLists.txt' or name.endswith('.cmake')


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description='Check CMake code against the style conventions.',
        formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    parser.add_argument('paths', nargs='*', default=[os.curdir],
                        help="The files or directories to check. For directories files named "
                        "'CMakeLists.txt' and ending in '.cmake' will be considered.")
    parser.add_argument('--exclude', metavar='filename', nargs='*', default=[],
                        dest='excludes', help='The filenames to exclude.')
    parser.add_argument('--filters', default='', help='Filters for lint_cmake')
    parser.add_argument('--linelength', metavar='N', type=int, default=140,
                        help='The maximum line length')
    parser.add_argument('--xunit-file', help='Generate a xunit compliant XML file')
    args = parser.parse_args(sys.argv[1:] if argv is None else argv)
    started = time.time()
    files = find_files(args.paths, _is_cmake, args.excludes)
    if not files:
        print('No files found', file=sys.stderr)
        return 1

    from cmakelint import main as cmakelint
    state = cmakelint._lint_state
    state.config = ''  # no ~/.cmakelintrc: results must not depend on the user
    state.errors = 0
    if args.filters:
        state.SetFilters(args.filters)
    state.SetLineLength(str(args.linelength))
    report_error = cmakelint.Error
    results = []
    for filename in files:
        errors: list[str] = []

        def collect(name: str, line: int, category: str, message: str,
                    errors: list[str] = errors) -> None:
            if cmakelint.ShouldPrintError(category):
                errors.append(f'{name}:{line}: {message} [{category}]')
            report_error(name, line, category, message)

        cmakelint.Error = collect
        try:
            cmakelint.ProcessFile(filename)
        finally:
            cmakelint.Error = report_error
        results.append((filename, errors))
        if errors:
            print('')
    print('')
    if state.errors:
        print(f'{state.errors} errors')
    else:
        print('No problems found')
    if args.xunit_file:
        write_xunit(args.xunit_file, 'ament_lint_cmake', results, started)
    return 1 if state.errors else 0


if __name__ == '__main__':
    sys.exit(main())
