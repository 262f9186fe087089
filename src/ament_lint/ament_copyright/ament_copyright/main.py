"""ament_copyright: every source file starts with a copyright notice and a known license.

Same command line and report lines as ament_lint's ament_copyright for checking (the
`--add-missing` / `--add-copyright-year` editing modes are not provided).
"""

from __future__ import annotations

import argparse
import os
import re
import sys
import time

from ament_copyright import get_licenses
from ament_copyright._lint import find_files, write_xunit

EXTENSIONS = ('c', 'cc', 'cpp', 'cxx', 'h', 'hh', 'hpp', 'hxx', 'cmake', 'py')
UNKNOWN = '<unknown>'
_COPYRIGHT = re.compile(r'^copyright(?:\s*\(c\)|\s*©)?\s+(\d{4}(?:\s*[-,]\s*\d{4})*),?\s+(.+)$',
                        re.IGNORECASE)


def _is_source(name: str) -> bool:
    return name == 'CMakeLists.txt' or ('.' in name and name.rsplit('.', 1)[-1] in EXTENSIONS)


def _header_comment(text: str) -> list[str]:
    """The lines of the comment block a file starts with, comment markers removed."""
    lines = text.splitlines()
    comment: list[str] = []
    in_block = False
    for number, line in enumerate(lines):
        stripped = line.strip()
        if in_block:
            end = stripped.find('*/')
            comment.append(stripped[:end] if end >= 0 else stripped)
            if end >= 0:
                in_block = False
            continue
        if number == 0 and stripped.startswith('#!'):
            continue
        if stripped.startswith('#') or stripped.startswith('//'):
            comment.append(stripped.lstrip('#/'))
        elif stripped.startswith('/*'):
            body = stripped[2:]
            if '*/' in body:
                comment.append(body[:body.index('*/')])
            else:
                comment.append(body)
                in_block = True
        elif not stripped and not comment:
            continue
        elif not stripped:
            comment.append('')
        else:
            break
    return [line.lstrip('* ').strip() if line.lstrip().startswith('*') else line.strip()
            for line in comment]


def _normalise(text: str) -> str:
    return ' '.join(text.split())


def check_file(path: str, licenses: dict) -> tuple[bool, str]:
    """(ok, message) for one file, message as upstream reports it."""
    try:
        with open(path, encoding='utf-8', errors='replace') as source:
            text = source.read()
    except OSError:
        return False, 'file not found'
    if not text.strip():
        return True, 'file empty'
    comment = _header_comment(text)
    copyrights = [m.group(1) + ' ' + m.group(2) for m in
                  (_COPYRIGHT.match(line) for line in comment) if m]
    if not copyrights:
        return False, 'could not find copyright notice'
    body = _normalise(' '.join(comment))
    license_name = next((key for key, entry in licenses.items()
                         if any(_normalise(h) in body for h in entry.file_headers)), UNKNOWN)
    return license_name != UNKNOWN, f"copyright={', '.join(copyrights)}, license={license_name}"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description='Check code files for copyright and license information.',
        formatter_class=argparse.ArgumentDefaultsHelpFormatter)
    parser.add_argument('paths', nargs='*', default=[os.curdir],
                        help='The files or directories to check. For directories files ending '
                        'in ' + ', '.join(f"'.{e}'" for e in EXTENSIONS) + ' (and '
                        "CMakeLists.txt) are considered, except in directories starting with "
                        "'.' or '_' and 'setup.py' files beside 'package.xml' files.")
    parser.add_argument('--exclude', metavar='filename', nargs='*', default=[],
                        dest='excludes', help='The filenames to exclude.')
    parser.add_argument('--list-licenses', action='store_true',
                        help='List names of known licenses')
    parser.add_argument('--verbose', action='store_true',
                        help='Show all files instead of only the ones with errors')
    parser.add_argument('--xunit-file', help='Generate a xunit compliant XML file')
    args = parser.parse_args(sys.argv[1:] if argv is None else argv)
    started = time.time()
    licenses = get_licenses()
    if args.list_licenses:
        for key in sorted(licenses):
            print(f'{key}: {licenses[key].name}')
        return 0

    files = [f for f in find_files(args.paths, _is_source, args.excludes)
             if not (os.path.basename(f) == 'setup.py' and
                     os.path.isfile(os.path.join(os.path.dirname(f), 'package.xml')))]
    if not files:
        print('No repository roots and files found')
    results = []
    for path in files:
        ok, message = check_file(path, licenses)
        if args.verbose or not ok:
            print(f'{path}: {message}', file=sys.stdout if ok else sys.stderr)
        results.append((path, [] if ok else [message]))
    errors = sum(1 for _, failed in results if failed)
    if errors:
        print(f'{errors} errors, checked {len(results)} files', file=sys.stderr)
    else:
        print(f'No problems found, checked {len(results)} files')
    if args.xunit_file:
        write_xunit(args.xunit_file, 'ament_copyright', results, started)
    return 1 if errors else 0


if __name__ == '__main__':
    sys.exit(main())
