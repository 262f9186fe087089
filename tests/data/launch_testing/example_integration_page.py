"""A launch test shaped like the Jazzy "Integration testing with launch_testing" page's:
turtlesim started by launch_ros; a test class whose class fixture inits rclpy once for its
tests (each setUpClass/tearDownClass is noted in $FIXTURE_LOG); a post-shutdown exit check."""
import os
import time
import unittest

import launch
import launch_ros.actions
import launch_testing
import launch_testing.actions
import launch_testing.asserts
import launch_testing.markers
import pytest
import rclpy
from turtlesim.msg import Pose


def note(line: str) -> None:
    with open(os.environ['FIXTURE_LOG'], 'a') as log:
        log.write(line + '\n')


@pytest.mark.launch_test
@launch_testing.markers.keep_alive
def generate_test_description():
    return launch.LaunchDescription([
        launch_ros.actions.Node(package='turtlesim', executable='turtlesim_node'),
        launch_testing.actions.ReadyToTest(),
    ])


class TestTurtleSim(unittest.TestCase):

    @classmethod
    def setUpClass(cls):
        note('setUpClass')
        rclpy.init()

    @classmethod
    def tearDownClass(cls):
        note('tearDownClass')
        rclpy.shutdown()

    def setUp(self):
        self.node = rclpy.create_node('test_turtlesim')

    def tearDown(self):
        self.node.destroy_node()

    def test_publishes_pose(self, proc_output):
        poses = []
        self.node.create_subscription(Pose, '/turtle1/pose', poses.append, 10)
        deadline = time.monotonic() + 20
        while not poses and time.monotonic() < deadline:
            rclpy.spin_once(self.node, timeout_sec=0.1)
        self.assertTrue(poses, 'no pose on /turtle1/pose within 20 s')
        self.assertAlmostEqual(poses[0].x, 5.544445, places=4)

    def test_logs_its_turtle(self, proc_output):
        proc_output.assertWaitFor('Spawning turtle [turtle1]', timeout=20)


@launch_testing.post_shutdown_test()
class TestTurtleSimShutdown(unittest.TestCase):

    def test_exit_codes(self, proc_info):
        launch_testing.asserts.assertExitCodes(proc_info)
