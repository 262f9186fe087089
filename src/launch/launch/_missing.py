"""Clear failures for the parts of upstream's launch API that this launch does not provide.

A launch file written for upstream that imports or uses something we lack must fail with one
line naming it, not with a traceback deep inside the import system.
"""

from __future__ import annotations

import os
from collections.abc import Callable


class MissingFeatureError(ImportError):
    """A launch file asked for an upstream launch feature this launch does not have."""


def module_getattr(module: str, directory: str | None = None) -> Callable[[str], object]:
    """A module-level `__getattr__` that names the missing feature.

    With `directory` (a package's own), names of its not yet imported submodules fall through
    as AttributeError, so `from package import submodule` still imports them.
    """
    def __getattr__(name: str) -> object:
        if name.startswith('_') or (directory is not None and (
                os.path.exists(os.path.join(directory, name + '.py'))
                or os.path.isdir(os.path.join(directory, name)))):
            raise AttributeError(name)
        raise MissingFeatureError(
            f'{module}.{name} is not supported by this launch (see docs/launch.md)')
    return __getattr__
