"""What the three checkers of this package share: finding files and writing xunit results."""

from __future__ import annotations

import os
import time
from collections.abc import Iterable
from xml.sax.saxutils import quoteattr


def find_files(paths: Iterable[str], accept, excludes: Iterable[str] = ()) -> list[str]:
    """Files under `paths` that `accept(name)`, skipping directories starting '.' or '_'."""
    excluded = {os.path.normpath(e) for e in excludes}
    found = []
    for path in paths:
        if os.path.isfile(path):
            found.append(path)
            continue
        for directory, subdirs, names in os.walk(path):
            subdirs[:] = sorted(d for d in subdirs if d[0] not in '._')
            for name in sorted(names):
                if accept(name):
                    found.append(os.path.normpath(os.path.join(directory, name)))
    return [f for f in found if os.path.normpath(f) not in excluded
            and os.path.basename(f) not in excluded]


def write_xunit(path: str, linter: str, results: list[tuple[str, list[str]]],
                started: float) -> None:
    """One testcase per checked file; a file's messages are its failure."""
    name = os.path.splitext(os.path.basename(path))[0].removesuffix('.xunit')
    package = os.path.basename(os.path.dirname(os.path.abspath(path)))
    failures = sum(1 for _, errors in results if errors)
    cases = []
    for filename, errors in results:
        case = f'  <testcase name={quoteattr(filename)} classname="{package}.{name}"'
        if errors:
            cases.append(case + '>\n    <failure message='
                         + quoteattr('\n'.join(errors)) + '/>\n  </testcase>')
        else:
            cases.append(case + '/>')
    if not results:
        cases.append(f'  <testcase name="{linter}.no_files_found" classname="{package}.{name}"/>')
    elapsed = time.time() - started
    xml = (f'<?xml version="1.0" encoding="UTF-8"?>\n'
           f'<testsuite name="{package}.{name}" tests="{max(len(results), 1)}" '
           f'failures="{failures}" errors="0" time="{elapsed:.3f}">\n'
           + '\n'.join(cases) + '\n</testsuite>\n')
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, 'w', encoding='utf-8') as out:
        out.write(xml)
