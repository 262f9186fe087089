"""`ros2 run logging_demo logging_demo_main`: logger_config and logger_usage_demo in one
process and one executor, as upstream's composed executable."""
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.executors import SingleThreadedExecutor

from logging_demo_py.logger_config import LoggerConfig
from logging_demo_py.logger_usage import LoggerUsage


def main() -> int:
    with ros_session() as stop:
        executor = SingleThreadedExecutor()
        executor.add_node(LoggerConfig())
        spin_until_stopped(LoggerUsage(), stop, executor)
    return 0
