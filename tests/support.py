"""The helpers of ws_testing (src/ws_testing) under their old name, for the tests that import
`from support import ...`; new tests import `from ws_testing import ...`."""

from ws_testing.support import *  # noqa: F403
from ws_testing.support import REPO  # noqa: F401 (named for readers: the repository root)
