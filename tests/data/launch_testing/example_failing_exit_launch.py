"""Must fail: the process under test exits with code 3."""
import os
import sys
import unittest

import launch
import launch.actions
import launch_testing
import launch_testing.actions
import launch_testing.asserts

TALKER = os.path.join(os.path.dirname(__file__), 'talker.py')


def generate_test_description():
    talker = launch.actions.ExecuteProcess(cmd=[sys.executable, TALKER, '1', '3'])
    return launch.LaunchDescription([
        talker,
        launch_testing.actions.ReadyToTest(),
    ]), {'talker': talker}


class TestTalker(unittest.TestCase):

    def test_finishes(self, proc_info, talker):
        proc_info.assertWaitForShutdown(process=talker, timeout=10)


@launch_testing.post_shutdown_test()
class TestExitCodes(unittest.TestCase):

    def test_exit_code(self, proc_info):
        launch_testing.asserts.assertExitCodes(proc_info)
