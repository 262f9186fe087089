"""Namespaces: absolute or relative, and one inside another."""

from __future__ import annotations


def is_root_namespace(ns: str) -> bool:
    return ns == '/'


def is_namespace_absolute(ns: str) -> bool:
    return ns.startswith('/')


def prefix_namespace(base_ns: str | None, ns: str | None) -> str | None:
    """`ns` inside `base_ns` when `ns` is relative; trailing '/' dropped (except the root).

    None when both are None; `base_ns` when `ns` is None; `ns` alone when it is absolute or
    there is no base.
    """
    if base_ns is None and ns is None:
        return None
    if ns is None:
        combined = base_ns
    elif not base_ns or is_namespace_absolute(ns):
        combined = ns
    else:
        combined = ('' if is_root_namespace(base_ns) else base_ns) + '/' + ns
    assert combined is not None
    return combined if is_root_namespace(combined) else combined.rstrip('/')


def make_namespace_absolute(ns: str | None) -> str | None:
    if ns is None:
        return None
    return ns if is_namespace_absolute(ns) else '/' + ns
