"""A launch test that starts a command mid-test with launch_testing.tools.launch_process and
reads its filtered output, as upstream's ros2cli tests start `ros2 ...`."""
import sys
import unittest

import launch.actions
import launch_testing.actions
import launch_testing.tools
import launch_testing.util
import pytest

import launch
import launch_testing


@pytest.mark.launch_test
def generate_test_description():
    return launch.LaunchDescription([
        launch_testing.util.KeepAliveProc(),
        launch_testing.actions.ReadyToTest(),
    ])


class TestMidTest(unittest.TestCase):

    def test_runs_a_command_mid_test(self, launch_service, proc_info, proc_output):
        command = launch.actions.ExecuteProcess(
            cmd=[sys.executable, '-c', 'print("pid 1\\nmid-test output")'],
            name='mid_test', output='screen')
        with launch_testing.tools.launch_process(
                launch_service, command, proc_info, proc_output,
                output_filter=launch_testing.tools.basic_output_filter()) as process:
            assert process.wait_for_shutdown(timeout=10)
        assert process.exit_code == 0
        assert launch_testing.tools.expect_output(
            expected_lines=['mid-test output'], text=process.output, strict=True)
