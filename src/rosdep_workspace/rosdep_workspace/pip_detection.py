"""rosdep's pip installer, asking this interpreter's metadata instead of running pip.

PyPI rosdep learns what is installed by running `pip3 freeze`, then `pip3 show` once for each
key that freeze did not list, each a new pip process of about a second: `rosdep check` took
10 s for two pip keys. rosdep runs in the workspace's interpreter, the one whose `pip3` it
would call, so `importlib.metadata` answers the same question from the same site-packages
(with pip show's name normalisation) in milliseconds.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from importlib import metadata


def installed(pkgs: Iterable[str], exec_fn: Callable | None = None) -> list[str]:
    """The keys of `pkgs` that are installed distributions (rosdep's `pip_detect` contract)."""
    found = []
    for pkg in pkgs:
        try:
            metadata.distribution(pkg)
        except (metadata.PackageNotFoundError, ValueError):
            continue
        found.append(pkg)
    return found


def use_metadata() -> None:
    """Make rosdep's pip installer detect through `installed` (before rosdep builds it)."""
    from rosdep2.platforms import pip
    pip.pip_detect = installed
