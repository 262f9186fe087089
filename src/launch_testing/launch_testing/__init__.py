"""launch_testing: integration tests of launched processes (upstream's API, on our launch).

A test file defines `generate_test_description()` returning a LaunchDescription with a
`launch_testing.actions.ReadyToTest()` in it; its unittest.TestCase classes run while the
processes run (active tests) or after they stopped (`@launch_testing.post_shutdown_test()`),
with `proc_info`, `proc_output`, `launch_service` and `test_args` injected. Run it with
`launch_test FILE`, with pytest (this package's plugin) or `add_launch_test()` in CMake.
See docs/testing.md.
"""

from launch_testing import tools
from launch_testing.decorator import post_shutdown_test
from launch_testing.io_handler import ActiveIoHandler, IoHandler
from launch_testing.parametrize import parametrize
from launch_testing.proc_info_handler import ActiveProcInfoHandler, ProcInfoHandler
from launch_testing.ready_aggregator import ReadyAggregator
from launch_testing.ready_to_test_action_timeout import ready_to_test_action_timeout

__all__ = [
    'ActiveIoHandler', 'ActiveProcInfoHandler', 'IoHandler', 'ProcInfoHandler',
    'ReadyAggregator', 'parametrize', 'post_shutdown_test', 'ready_to_test_action_timeout',
    'tools',
]
