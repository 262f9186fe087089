"""ament_xmllint: XML files are well-formed and package manifests valid.

Upstream validates against the schema named by `<?xml-model href=...?>`, which xmllint
downloads (download.ros.org). This machine has no internet, so the schema step is replaced by
catkin_pkg's manifest validation for package.xml files, and the output says so on each file.
Well-formedness is checked by the `xmllint` program (libxml2-utils) when it is installed,
otherwise by Python's expat parser (also said in the output).
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

from ament_copyright._lint import find_files, write_xunit

EXTENSIONS = ('xml',)


def _well_formed(filename: str, xmllint: str | None) -> list[str]:
    if xmllint:
        done = subprocess.run([xmllint, '--noout', '--nonet', filename],
                              capture_output=True, text=True, timeout=60)
        return [line for line in (done.stdout + done.stderr).splitlines() if line] \
            if done.returncode else []
    try:
        ET.parse(filename)
    except ET.ParseError as error:
        return [f'{filename}: {error}']
    return []


def _manifest_errors(filename: str) -> list[str]:
    from catkin_pkg.package import InvalidPackage, parse_package
    try:
        parse_package(filename, warnings=[])
    except InvalidPackage as error:
        return [' '.join(str(error).split())]
    return []


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description='Check XML markup using xmllint.',
        formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    parser.add_argument('paths', nargs='*', default=[os.curdir],
                        help="The files or directories to check. For directories files ending "
                        "in '.xml' will be considered.")
    parser.add_argument('--exclude', metavar='filename', nargs='*', default=[],
                        dest='excludes', help='The filenames to exclude.')
    parser.add_argument('--extensions', nargs='*', default=list(EXTENSIONS),
                        help='The file extensions of the files to check')
    parser.add_argument('--xunit-file', help='Generate a xunit compliant XML file')
    args = parser.parse_args(sys.argv[1:] if argv is None else argv)
    started = time.time()
    suffixes = tuple('.' + e for e in args.extensions)
    files = find_files(args.paths, lambda name: name.endswith(suffixes), args.excludes)
    if not files:
        print('No files found', file=sys.stderr)
        return 1
    xmllint = shutil.which('xmllint')
    if not xmllint:
        print("'xmllint' not found (apt-get install libxml2-utils): checking well-formedness "
              "with Python's XML parser instead")
    results = []
    for filename in files:
        errors = _well_formed(filename, xmllint)
        note = ''
        if not errors and os.path.basename(filename) == 'package.xml':
            errors = _manifest_errors(filename)
            note = (' (schema not downloaded, no network: manifest checked with catkin_pkg '
                    'instead)')
        if errors:
            print(f"File '{filename}' is invalid:", file=sys.stderr)
            for line in errors:
                print(line, file=sys.stderr)
            print('', file=sys.stderr)
        else:
            print(f"File '{filename}' is valid{note}")
            print('')
        results.append((filename, errors))
    invalid = sum(1 for _, errors in results if errors)
    if invalid:
        print(f'{invalid} files are invalid', file=sys.stderr)
    else:
        print('No problems found')
    if args.xunit_file:
        write_xunit(args.xunit_file, 'ament_xmllint', results, started)
    return 1 if invalid else 0


if __name__ == '__main__':
    sys.exit(main())
