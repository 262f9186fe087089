"""basic_output_filter with the output lines an RMW implementation is known to print.

An RMW package may register, in the ament index, resources `rmw_output_prefixes` and
`rmw_output_patterns` (one filter per line): lines its middleware prints that tests of a
command's output should ignore.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

import ament_index_python
from launch_testing.tools.output import (
    basic_output_filter as plain_output_filter,
)
from launch_testing.tools.output import (
    get_default_filtered_patterns,
    get_default_filtered_prefixes,
)

_FILTER_TYPES = ('prefixes', 'patterns')


def get_rmw_output_filter(rmw_implementation: str, filter_type: str) -> list[str]:
    if filter_type not in _FILTER_TYPES:
        raise TypeError(f'Unsupported filter_type "{filter_type}". Supported types: '
                        f'{list(_FILTER_TYPES)}')
    resource = f'rmw_output_{filter_type}'
    if not ament_index_python.has_resource(resource, rmw_implementation):
        return []
    content, _ = ament_index_python.get_resource(resource, rmw_implementation)
    return content.splitlines()


def basic_output_filter(filtered_prefixes: Iterable[str] | None = None,
                        filtered_patterns: Iterable[str] | None = None,
                        filtered_rmw_implementation: str | None = None
                        ) -> Callable[[str], str]:
    prefixes = list(get_default_filtered_prefixes() if filtered_prefixes is None
                    else filtered_prefixes)
    patterns = list(get_default_filtered_patterns() if filtered_patterns is None
                    else filtered_patterns)
    if filtered_rmw_implementation:
        prefixes += get_rmw_output_filter(filtered_rmw_implementation, 'prefixes')
        patterns += get_rmw_output_filter(filtered_rmw_implementation, 'patterns')
    return plain_output_filter(prefixes, patterns)
