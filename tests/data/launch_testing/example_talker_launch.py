"""A launch test as upstream's examples write one: a process, ReadyToTest, an active test
waiting for its output, a post-shutdown test of its exit code."""
import os
import sys
import unittest

import launch
import launch.actions
import launch_testing
import launch_testing.actions
import launch_testing.asserts
import pytest

TALKER = os.path.join(os.path.dirname(__file__), 'talker.py')


@pytest.mark.launch_test
def generate_test_description():
    talker = launch.actions.ExecuteProcess(cmd=[sys.executable, TALKER, '3'], output='screen')
    return launch.LaunchDescription([
        talker,
        launch_testing.actions.ReadyToTest(),
    ]), {'talker': talker}


class TestTalker(unittest.TestCase):

    def test_talks(self, proc_output, talker):
        proc_output.assertWaitFor('Hello World: 2', process=talker, timeout=10, stream='stdout')


@launch_testing.post_shutdown_test()
class TestTalkerShutdown(unittest.TestCase):

    def test_exit_code(self, proc_info):
        launch_testing.asserts.assertExitCodes(proc_info)
