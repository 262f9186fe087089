"""A ROS launch test: turtlesim started by launch_ros, its pose seen with WaitForTopics."""
import unittest

import launch
import launch_ros.actions
import launch_testing.actions
import launch_testing.asserts
from launch_testing_ros import WaitForTopics
from turtlesim.msg import Pose


def generate_test_description():
    return launch.LaunchDescription([
        launch_ros.actions.Node(package='turtlesim', executable='turtlesim_node', name='sim'),
        launch_testing.actions.ReadyToTest(),
    ])


class TestTurtlesim(unittest.TestCase):

    def test_pose_is_published(self, proc_output):
        proc_output.assertWaitFor('Spawning turtle [turtle1]', timeout=20)
        with WaitForTopics([('/turtle1/pose', Pose)], timeout=20.0) as wait_for_node:
            pose = wait_for_node.received_messages('/turtle1/pose')[0]
        self.assertAlmostEqual(pose.x, 5.544445, places=4)


@launch_testing.post_shutdown_test()
class TestShutdown(unittest.TestCase):

    def test_exit_code(self, proc_info):
        launch_testing.asserts.assertExitCodes(proc_info)
