"""build_text_match / build_line_match: find a string, a regex, or a sequence of them in
process output (as text, or as a list of lines)."""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Iterable
from typing import Any

_ANSI_ESCAPE = re.compile(r'\x1b\[[0-9;?]*[ -/]*[@-~]')


def strip_ansi(text: str) -> str:
    """Text without terminal colour and cursor sequences."""
    return _ANSI_ESCAPE.sub('', text)


def normalize_lineseps(text: str) -> str:
    r"""os.linesep and '\r\n' (a pseudo-terminal's line end) as '\n'."""
    return text.replace(os.linesep, '\n').replace('\r\n', '\n')


def _sequence(parts: list[Callable[..., Any]], strict: bool) -> Callable[..., Any]:
    """Each part found after the previous one; with strict, each right where the last ended
    (the first at `start`)."""
    def match(actual: Any, start: int = 0) -> tuple[int, int] | None:
        first = end = None
        for part in parts:
            at = start if end is None else end
            found = part(actual, at)
            if found is None or (strict and found[0] != at):
                return None
            first = found[0] if first is None else first
            end = found[1]
        return (start, start) if first is None or end is None else (first, end)
    return match


def build_text_match(expected: Any, *, strict: bool = False) -> Callable[..., Any]:
    """A function (text, start=0) -> (start, end) of the first match, or None.

    `expected` is a str (a substring; with strict, all of the rest of the text), a compiled
    regex (searched; with strict, matched at `start`), or an iterable of those, matched one
    after the other.
    """
    if isinstance(expected, str):
        def match_str(text: str, start: int = 0) -> tuple[int, int] | None:
            text = normalize_lineseps(text)
            if strict:
                return (start, start + len(expected)) if text[start:] == expected else None
            found = text.find(expected, start)
            return None if found < 0 else (found, found + len(expected))
        return match_str
    if hasattr(expected, 'search') and hasattr(expected, 'match'):
        def match_regex(text: str, start: int = 0) -> tuple[int, int] | None:
            text = normalize_lineseps(text)
            found = expected.match(text, start) if strict else expected.search(text, start)
            return None if found is None else (found.start(), found.end())
        return match_regex
    if isinstance(expected, Iterable):
        sequence = _sequence([build_text_match(part) for part in expected], strict)
        return lambda text, start=0: sequence(normalize_lineseps(text), start)
    raise ValueError(f'expected output must be a str, a regex or a list of them, not '
                     f'{type(expected).__name__}')


def build_line_match(expected: Any, *, strict: bool = False) -> Callable[..., Any]:
    """A function (lines, start=0) -> (first, end) line indices of the match, or None.

    `expected` is a str (a line containing it), a compiled regex (a line it matches), or an
    iterable of those, found in order; with strict every line must be matched, in order.
    """
    if isinstance(expected, str) or hasattr(expected, 'match'):
        def hit(line: str) -> bool:
            return expected in line if isinstance(expected, str) else bool(
                expected.match(line))

        def match_line(lines: list[str], start: int = 0) -> tuple[int, int] | None:
            if strict:
                rest = lines[start:]
                return (start, start + len(rest)) if all(hit(line) for line in rest) else None
            return next(((i, i + 1) for i in range(start, len(lines)) if hit(lines[i])), None)
        return match_line
    if isinstance(expected, Iterable):
        return _sequence([build_line_match(part) for part in expected], strict)
    raise ValueError('expected lines must be a str, a regex or a list of them, not '
                     f'{type(expected).__name__}')
