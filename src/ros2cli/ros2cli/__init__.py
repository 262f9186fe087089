"""The `ros2` command of this workspace (ros2cli's verbs and output formats)."""


def _quiet_ctrl_c_while_starting() -> None:
    """Ctrl-C while the `ros2` command still imports would print a KeyboardInterrupt
    traceback before cli.main() takes over Ctrl-C: end quietly with 130, as a shell reports
    Ctrl-C."""
    import os
    import signal
    import sys
    import threading
    from pathlib import Path

    if (sys.argv and Path(sys.argv[0]).name == 'ros2'
            and threading.current_thread() is threading.main_thread()
            and signal.getsignal(signal.SIGINT) is signal.default_int_handler):
        # os._exit, not sys.exit: a SystemExit raised inside rclpy's C++ calls can be lost,
        # and the process then ignored that Ctrl-C (seen). Nothing is running yet to clean up.
        signal.signal(signal.SIGINT, lambda _signum, _frame: os._exit(130))


_quiet_ctrl_c_while_starting()
