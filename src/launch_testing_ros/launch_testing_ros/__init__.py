"""launch_testing_ros: ROS helpers for launch tests (upstream's names)."""
from launch_testing.test_runner import LaunchTestRunner

from launch_testing_ros.wait_for_topics import WaitForTopics

__all__ = ['LaunchTestRunner', 'WaitForTopics']
