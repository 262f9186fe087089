"""Must fail: the active test waits for output that never comes."""
import os
import sys
import unittest

import launch
import launch.actions
import launch_testing
import launch_testing.actions
import launch_testing.markers

TALKER = os.path.join(os.path.dirname(__file__), 'talker.py')


@launch_testing.markers.keep_alive
def generate_test_description():
    return launch.LaunchDescription([
        launch.actions.ExecuteProcess(cmd=[sys.executable, TALKER, '2']),
        launch_testing.actions.ReadyToTest(),
    ])


class TestTalker(unittest.TestCase):

    def test_says_goodbye(self, proc_output):
        proc_output.assertWaitFor('Goodbye', timeout=2, stream='stdout')
