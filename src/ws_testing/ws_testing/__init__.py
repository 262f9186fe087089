"""The workspace's test helpers: `from ws_testing import RosProcess, TestNode, leased_domain`.

The names come from ws_testing.support on first use: the pytest plugin (ws_testing.plugin),
loaded by every pytest run of the environment, imports this package, and should not load rclpy
for a run that uses none of it.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from ws_testing.support import *  # noqa: F403
    from ws_testing.workspace import *  # noqa: F403

# The submodules whose public names this package hands out, looked up in this order.
_MODULES = ('ws_testing.support', 'ws_testing.workspace')


def __getattr__(name: str) -> Any:
    if not name.startswith('_'):
        for module_name in _MODULES:
            module = importlib.import_module(module_name)
            if hasattr(module, name):
                return getattr(module, name)
    raise AttributeError(f'module {__name__!r} has no attribute {name!r}')
