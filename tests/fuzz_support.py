"""ws_testing.fuzz under its old name, for the tests that import `from fuzz_support import ...`."""

from ws_testing.fuzz import *  # noqa: F403
