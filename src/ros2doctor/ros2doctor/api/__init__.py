"""What every check and report shares: results, reports, and Jazzy's output formats."""

from __future__ import annotations

import warnings
from dataclasses import dataclass, field
from typing import TextIO


@dataclass
class Result:
    """Errors fail a check; warnings fail it only with --include-warnings."""

    error: int = 0
    warning: int = 0

    def warn(self, message: str) -> None:
        _emit(message)
        self.warning += 1

    def fail(self, message: str) -> None:
        _emit(f'ERROR: {message}')
        self.error += 1


@dataclass
class Report:
    """A titled list of (item, value) lines, printed as Jazzy's `ros2 doctor --report`."""

    name: str
    items: list[tuple[str, object]] = field(default_factory=list)

    def add(self, item: str, value: object) -> None:
        self.items.append((item, value))


def _emit(message: str) -> None:
    """`<file>: <line>: UserWarning: <message>` on stderr, as ros2doctor's warnings look."""
    def formatwarning(msg, category, filename, lineno, line=None) -> str:
        return f'{filename}: {lineno}: {category.__name__}: {msg}\n'

    with warnings.catch_warnings():
        warnings.simplefilter('always')
        default = warnings.formatwarning
        warnings.formatwarning = formatwarning
        try:
            # stacklevel 3: the line of the check that called Result.warn/fail.
            warnings.warn(message, UserWarning, stacklevel=3)
        finally:
            warnings.formatwarning = default


def format_report(report: Report) -> str:
    """Blank line, the title indented by three, then `item<padding>: value` lines."""
    lines = ['', '   ' + report.name]
    if report.items:
        longest = max(len(name) for name, _ in report.items)
        padding = longest + 4 if longest >= 8 else 8
        lines += [f'{name:{padding}}: {value}' for name, value in report.items]
    return '\n'.join(lines)


def print_report(report: Report, out: TextIO) -> None:
    print(format_report(report), file=out, flush=True)
