"""What the workspace's long-running nodes share (an rclpy helper library, like rclpy's own).

- `spinning`: rclpy.init with our own SIGINT/SIGTERM handlers and a spin loop that ends
  cleanly (exit 0, no traceback) on Ctrl-C or SIGTERM.
- `discovery`: the Fast DDS profile that announces participants every 0.5 s and gives each
  start a fresh participant id.
- `parameter_guard`: rclpy's parameter services refuse malformed requests instead of dying.
- `repeat_log`: a repeated log line at most once per period, with a count of those left out.
- `quiet_ctrl_c_while_starting` (here, so importing it costs nothing): Ctrl-C during start-up.

Importing this package imports nothing else: executables call quiet_ctrl_c_while_starting
before rclpy is loaded.
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
