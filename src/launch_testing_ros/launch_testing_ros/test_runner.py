"""launch_testing_ros.test_runner.LaunchTestRunner: launch_testing's runner (upstream keeps
a ROS-specific name for it)."""

import launch_testing.test_runner


class LaunchTestRunner(launch_testing.test_runner.LaunchTestRunner):
    pass
