"""Log as tf2's C++ core and tools do: on rcutils' unnamed logger, `[WARN] [time] []: ...`.

rclpy's get_logger() refuses an empty name, so this goes one level down, to the rcutils call
every rclpy logger ends in.
"""
from rclpy.impl.implementation_singleton import rclpy_implementation as _rclpy
from rclpy.logging import LoggingSeverity

ERROR = LoggingSeverity.ERROR
WARN = LoggingSeverity.WARN


def log(severity: LoggingSeverity, message: str) -> None:
    _rclpy.rclpy_logging_rcutils_log(severity, '', message, 'tf2', 'tf2', 0)
