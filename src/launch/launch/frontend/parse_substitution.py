"""Upstream's substitution syntax in attribute values: `$(var name)`, `$(find-pkg-share p)/x`.

Each `$(name args...)` becomes the substitution registered for `name` (expose_substitution);
arguments may be quoted and may hold substitutions themselves.
"""

from __future__ import annotations

import re
from typing import Any

from launch.frontend.entity import FrontendError
from launch.frontend.expose import instantiate_substitution
from launch.substitution import Substitution
from launch.substitutions.text_substitution import TextSubstitution


def replace_escaped_characters(data: str) -> str:
    """`\\x` is a literal x (so `\\$(` is not a substitution)."""
    return re.sub(r'\\(.)', r'\1', data)


def parse_substitution(string_value: str) -> list[Substitution]:
    """The substitutions of a text (upstream's name); empty text is one empty text."""
    if not string_value:
        return [TextSubstitution(text=string_value)]
    return parse_substitutions(string_value)


def parse_if_substitutions(value: Any) -> Any:
    """Text with substitutions as substitutions, plain text as text, anything else as is.

    A list is done item by item and must be uniform (all text, or all one type).
    """
    kinds: set[type] = set()

    def one(item: Any) -> Any:
        if isinstance(item, str):
            output = parse_substitution(item)
            if len(output) == 1 and isinstance(output[0], TextSubstitution):
                kinds.add(str)
                return output[0].text
            return output
        kinds.add(type(item))
        return item

    output = [one(item) for item in value] if isinstance(value, list) else one(value)
    if len(kinds) > 1:
        raise ValueError('The result is a non-uniform list')
    return output


def parse_substitutions(text: Any) -> list[Substitution]:
    """The substitutions of an attribute value (text, or a YAML bool/number)."""
    from launch.frontend.parser import Parser
    Parser.load_launch_extensions()  # the `$(name)` registrations
    if isinstance(text, bool):
        text = str(text).lower()
    text = str(text)
    return _parse_text(text, 0, stop=None)[0]


def _parse_text(text: str, i: int, stop: str | None, quote: str | None = None
                ) -> tuple[list[Substitution], int]:
    """Text up to a `stop` character; `quote`: the quoted argument this text is inside."""
    parts: list[Substitution] = []
    literal = ''
    while i < len(text):
        if text.startswith('$(', i):
            if literal:
                parts.append(TextSubstitution(text=literal))
                literal = ''
            sub, i = _parse_call(text, i + 2, quote)
            parts.append(sub)
            continue
        if stop is not None and text[i] in stop:
            break
        if text[i] == '\\' and i + 1 < len(text):
            literal += text[i + 1]
            i += 2
            continue
        literal += text[i]
        i += 1
    if literal:
        parts.append(TextSubstitution(text=literal))
    return parts, i


def _parse_call(text: str, i: int, quote: str | None) -> tuple[Substitution, int]:
    """`name args...)`; inside a quoted argument, the arguments of a nested substitution
    are not quoted again: a quote of the other kind is a plain character there."""
    start = i
    while i < len(text) and not text[i].isspace() and text[i] != ')':
        i += 1
    name = text[start:i]
    args: list[list[Substitution]] = []
    while True:
        while i < len(text) and text[i].isspace():
            i += 1
        if i >= len(text):
            raise FrontendError(f"unterminated substitution '$({text[start:]}'")
        if text[i] == ')':
            i += 1
            break
        if quote is None and text[i] in '\'"':
            arg, i = _parse_text(text, i + 1, stop=text[i], quote=text[i])
            i += 1
        else:
            arg, i = _parse_text(text, i, stop=' \t\n)' + (quote or ''), quote=quote)
        args.append(arg)
    return instantiate_substitution(name, args), i

