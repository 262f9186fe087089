"""launch_testing_ros: ROS helpers for launch tests (upstream's names)."""

from launch_testing_ros import tools
from launch_testing_ros.data_republisher import DataRepublisher
from launch_testing_ros.message_pump import MessagePump
from launch_testing_ros.test_runner import LaunchTestRunner
from launch_testing_ros.wait_for_topics import WaitForTopics

__all__ = ['DataRepublisher', 'LaunchTestRunner', 'MessagePump', 'WaitForTopics', 'tools']
