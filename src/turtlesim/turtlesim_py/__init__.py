"""Python implementation of the turtlesim simulator and its tutorial executables.

The generated interface package is called `turtlesim`; this code lives in `turtlesim_py`.
"""


def quiet_ctrl_c_while_starting(package: str) -> None:
    """Ctrl-C while one of `package`'s executables (in lib/<package>/) still imports would
    print a KeyboardInterrupt traceback (main() installs its own handlers only after rclpy
    is imported): end quietly with 130, as a shell reports Ctrl-C."""
    import os
    import signal
    import sys
    import threading
    from pathlib import Path

    if (sys.argv and Path(sys.argv[0]).parent.name == package
            and threading.current_thread() is threading.main_thread()
            and signal.getsignal(signal.SIGINT) is signal.default_int_handler):
        # os._exit, not sys.exit: a SystemExit raised inside rclpy's C++ calls can be lost,
        # and the process then ignored that Ctrl-C (seen). Nothing is running yet to clean up.
        signal.signal(signal.SIGINT, lambda _signum, _frame: os._exit(130))


quiet_ctrl_c_while_starting('turtlesim')
