"""build_text_match: find a string, a regex, or a sequence of them in process output."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any

Match = Callable[[str, int], 'tuple[int, int] | None']


def normalize_lineseps(text: str) -> str:
    r"""'\r\n' (a pseudo-terminal's line end) as '\n'."""
    return text.replace('\r\n', '\n')


def build_text_match(expected: Any, *, strict: bool = False) -> Callable[..., Any]:
    """A function (text, start=0) -> (start, end) of the first match, or None.

    `expected` is a str (found as a substring), a compiled regex (searched), or an iterable
    of those, matched one after the other. With strict, the whole text must match.
    """
    if isinstance(expected, str):
        def match_str(text: str, start: int = 0) -> tuple[int, int] | None:
            text = normalize_lineseps(text)
            if strict:
                return (start, len(text)) if text[start:] == expected else None
            found = text.find(expected, start)
            return None if found < 0 else (found, found + len(expected))
        return match_str
    if hasattr(expected, 'search'):
        def match_regex(text: str, start: int = 0) -> tuple[int, int] | None:
            text = normalize_lineseps(text)
            found = (expected.fullmatch(text, start) if strict
                     else expected.search(text, start))
            return None if found is None else (found.start(), found.end())
        return match_regex
    if isinstance(expected, Iterable):
        parts = [build_text_match(part) for part in expected]

        def match_sequence(text: str, start: int = 0) -> tuple[int, int] | None:
            first = end = None
            for part in parts:
                found = part(text, start if end is None else end)
                if found is None:
                    return None
                first = found[0] if first is None else first
                end = found[1]
            if first is None or end is None:
                return (start, start)
            return first, end
        return match_sequence
    raise ValueError(f'expected output must be a str, a regex or a list of them, not '
                     f'{type(expected).__name__}')
