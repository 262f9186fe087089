"""Remapping rules (from, to) as tuples of substitutions."""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from typing import Any

from launch.utilities import ensure_argument_type, normalize_to_list_of_substitutions

RemapRule = tuple[tuple[Any, ...], tuple[Any, ...]]


def normalize_remap_rule(remap_rule: Any) -> RemapRule:
    ensure_argument_type(remap_rule, tuple, 'remap_rule')
    if len(remap_rule) != 2:
        raise TypeError(f'remap_rule must be a tuple of length 2, got length {len(remap_rule)}')
    return (tuple(normalize_to_list_of_substitutions(remap_rule[0])),
            tuple(normalize_to_list_of_substitutions(remap_rule[1])))


def normalize_remap_rules(remap_rules: Iterable[Any]) -> Iterator[RemapRule]:
    yield from map(normalize_remap_rule, remap_rules)
