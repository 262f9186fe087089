"""ws_testing.browser under its old name, for the tests that import `from rqt_browser ...`."""

from ws_testing.browser import *  # noqa: F403
