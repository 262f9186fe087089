"""ament_lint_skip: record a linter test as skipped, with the reason, in its xunit file.

ament_lint_common adds such a test in place of a linter whose program is not installed, so
`colcon test` says what did not run and why instead of failing or passing silently.
"""

from __future__ import annotations

import argparse
import os
import sys
from xml.sax.saxutils import quoteattr


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description='Record a skipped linter test.')
    parser.add_argument('--xunit-file', required=True, help='The xunit file to write')
    parser.add_argument('--reason', required=True, help='Why the linter did not run')
    args = parser.parse_args(sys.argv[1:] if argv is None else argv)
    name = os.path.basename(args.xunit_file).split('.', 1)[0]
    package = os.path.basename(os.path.dirname(os.path.abspath(args.xunit_file)))
    print(f'{name}: skipped: {args.reason}')
    os.makedirs(os.path.dirname(os.path.abspath(args.xunit_file)), exist_ok=True)
    with open(args.xunit_file, 'w', encoding='utf-8') as out:
        out.write('<?xml version="1.0" encoding="UTF-8"?>\n'
                  f'<testsuite name="{package}.{name}" tests="1" failures="0" errors="0" '
                  'skipped="1" time="0">\n'
                  f'  <testcase name="{name}" classname="{package}.{name}">\n'
                  f'    <skipped type="skip" message={quoteattr(args.reason)}/>\n'
                  '  </testcase>\n</testsuite>\n')
    return 0


if __name__ == '__main__':
    sys.exit(main())
