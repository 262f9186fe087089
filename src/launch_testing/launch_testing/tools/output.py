"""Output helpers for tests that read a process's output: line filters and expectations."""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Iterable
from typing import Any

from launch_testing.tools.text import build_line_match, build_text_match, strip_ansi

_DEFAULT_PREFIXES = ('pid', 'rc')  # lines launch's legacy output helpers print


def get_default_filtered_prefixes() -> list[str]:
    return list(_DEFAULT_PREFIXES)


def get_default_filtered_patterns() -> list[str]:
    return []


def basic_output_filter(filtered_prefixes: Iterable[str] | None = None,
                        filtered_patterns: Iterable[str] | None = None
                        ) -> Callable[[str], str]:
    """A function dropping the lines that start with one of the prefixes (default: 'pid',
    'rc') or match one of the regexes (from the line's start)."""
    prefixes = tuple(get_default_filtered_prefixes() if filtered_prefixes is None
                     else filtered_prefixes)
    patterns = [re.compile(p) for p in (get_default_filtered_patterns()
                                        if filtered_patterns is None else filtered_patterns)]

    def output_filter(output: str) -> str:
        return ''.join(line for line in output.splitlines(keepends=True)
                       if not line.startswith(prefixes)
                       and not any(p.match(line) for p in patterns))
    return output_filter


def expected_output_from_file(path: str, encoding: str | None = None) -> list[Any]:
    """The lines of `path`.txt, or the regexes of `path`.regex (one per line)."""
    if os.path.isfile(path + '.txt'):
        with open(path + '.txt', encoding=encoding) as handle:
            return handle.read().splitlines()
    if os.path.isfile(path + '.regex'):
        with open(path + '.regex', encoding=encoding) as handle:
            return [re.compile(line) for line in handle.read().splitlines()]
    raise RuntimeError(f'could not find output check file: {path}')


def expect_output(text: str | None = None, *, lines: list[str] | None = None,
                  expected_text: Any = None, expected_lines: Any = None,
                  strip_ansi_escape_sequences: bool = True, strict: bool = False) -> bool:
    """Whether the output (text or lines) shows the expected text or lines (see
    build_text_match / build_line_match); with strict, nothing else may be there."""
    if (text is None) == (lines is None):
        raise ValueError('Either lines or text, but not both, must be specified')
    if (expected_text is None) == (expected_lines is None):
        raise ValueError('Either expected lines or text, but not both, must be specified')
    if expected_text is not None:
        text = '\n'.join(lines or []) if text is None else text
        if strip_ansi_escape_sequences:
            text = strip_ansi(text)
        return build_text_match(expected_text, strict=strict)(text) is not None
    lines = text.splitlines() if lines is None else lines
    if strip_ansi_escape_sequences:
        lines = [strip_ansi(line) for line in lines]
    return build_line_match(expected_lines, strict=strict)(lines) is not None
