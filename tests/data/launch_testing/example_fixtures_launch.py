"""A launch test whose class fixtures say when they run (each must run once), whose tests read
the launch argument `who` (given as who:=NAME)."""
import sys
import unittest

import launch.actions
import launch.substitutions
import launch_testing.actions
import launch_testing.util
import pytest

import launch
import launch_testing


@pytest.mark.launch_test
def generate_test_description():
    return launch.LaunchDescription([
        launch.actions.DeclareLaunchArgument('who', default_value='nobody'),
        launch.actions.ExecuteProcess(
            cmd=[sys.executable, '-c', 'import sys; print("hello", sys.argv[1])',
                 launch.substitutions.LaunchConfiguration('who')],
            name='greeter', output='screen'),
        launch_testing.util.KeepAliveProc(),
        launch_testing.actions.ReadyToTest(),
    ])


class TestWhileRunning(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        print('fixture: active setUpClass', flush=True)

    @classmethod
    def tearDownClass(cls):
        print('fixture: active tearDownClass', flush=True)

    def test_greets_the_launch_argument(self, proc_info, proc_output, test_args):
        proc_output.assertWaitFor(f"hello {test_args['who']}", process='greeter',
                                  timeout=10, stream='stdout')
        proc_info.assertWaitForShutdown(process='greeter', timeout=10)


@launch_testing.post_shutdown_test()
class TestAfterShutdown(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        print('fixture: post-shutdown setUpClass', flush=True)

    @classmethod
    def tearDownClass(cls):
        print('fixture: post-shutdown tearDownClass', flush=True)

    def test_greeter_exit_code(self, proc_info):
        launch_testing.asserts.assertExitCodes(proc_info, process='greeter')
