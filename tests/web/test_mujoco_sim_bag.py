"""Recording and replay of a simulation run, as docs/simulation.md has the learner do it:
`ros2 bag record -a` beside `diffbot_sim.launch.py` while the robot turns, then, with the
simulator gone, `ros2 bag play` of that bag into the RViz page with diffbot.rviz. The page draws
the robot (its description and static frames are latched in the bag), the scan, the odometry
and the camera image from the bag alone, and the replayed scans are the recorded ones."""

from __future__ import annotations

from pathlib import Path

import pytest
from geometry_msgs.msg import Twist, Vector3
from rosgraph_msgs.msg import Clock
from sensor_msgs.msg import LaserScan
from test_mujoco_sim_rviz import DIFFBOT_LINKS

from rqt_browser import chromium_missing
from support import RosProcess, TestNode
from ws_testing.browser import rviz_page

RECORDED = ('/clock', '/scan', '/odom', '/tf', '/tf_static', '/camera/image_raw',
            '/robot_description')


def test_recorded_run_replays_into_the_rviz_page(tmp_path: Path, domain: int,
                                                 ros_env) -> None:
    reason = chromium_missing()
    if reason:
        pytest.skip(reason)
    from ament_index_python.packages import get_package_share_directory

    config = Path(get_package_share_directory('diffbot_bringup')) / 'rviz' / 'diffbot.rviz'
    bag = tmp_path / 'run'
    probe = TestNode(domain)
    try:
        bringup = RosProcess(['ros2', 'launch', 'diffbot_bringup', 'diffbot_sim.launch.py',
                              'rviz:=false'], ros_env, tmp_path / 'launch.log')
        try:
            bringup.wait_for_output(r'\[robot_state_publisher-2\] .*Robot initialized',
                                    timeout=30)
            # Turn on the spot (the simulator keeps the last /cmd_vel), so every scan differs
            # from the one before.
            scans = probe.collect(LaserScan, '/scan')
            cmd = probe.node.create_publisher(Twist, '/cmd_vel', 10)
            probe.spin_until(lambda: cmd.get_subscription_count() > 0, 10, 'the sim on /cmd_vel')
            cmd.publish(Twist(angular=Vector3(z=1.0)))
            recorder = RosProcess(['ros2', 'bag', 'record', '-a', '-o', str(bag)], ros_env,
                                  tmp_path / 'record.log')
            for topic in RECORDED:
                recorder.wait_for_output(f"Subscribed to topic '{topic}'", timeout=20)
            probe.spin_for(0.5)
            assert recorder.stop() == 0, recorder.output
        finally:
            assert bringup.stop() == 0, bringup.output
        recorded = {(s.header.stamp.sec, s.header.stamp.nanosec): list(s.ranges)
                    for s in scans}
        assert len(recorded) >= 5, len(recorded)

        # The bag plays while the page starts: the robot description and the static frames,
        # recorded once, reach the page because the player offers them transient-local.
        heard = probe.collect(LaserScan, '/scan')
        clocks = probe.collect(Clock, '/clock')
        player = RosProcess(['ros2', 'bag', 'play', str(bag), '--loop'], ros_env,
                            tmp_path / 'play.log')
        with rviz_page(ros_env, probe, config, tmp_path) as (_server, page):
            page.wait_for_function(
                '''() => window.rviz && window.rviz.ready
                    && ['RobotModel', 'LaserScan', 'Odometry', 'Camera'].every(
                        (name) => window.rviz.status[name] === 'OK')
                    && window.rviz.images.Camera && window.rviz.images.Camera.drawn > 0
                    && window.rviz.links.length >= 6''', timeout=20000)
            state = page.evaluate('window.rviz')
        assert player.stop() == 0, player.output
    finally:
        probe.close()
    assert set(state['links']) >= DIFFBOT_LINKS, state['links']
    camera = state['images']['Camera']
    assert (camera['width'], camera['height'], camera['encoding']) == (320, 240, 'rgb8')
    # What was played is what was recorded: each replayed scan is one of the run's.
    assert heard, 'no /scan replayed'
    for scan in heard:
        key = (scan.header.stamp.sec, scan.header.stamp.nanosec)
        if key in recorded:
            assert list(scan.ranges) == recorded[key]
    # The run's /clock plays too (sim time: seconds since the simulator started, not the
    # wall clock), for use_sim_time nodes to follow.
    last = max(recorded)[0]
    assert clocks and all(0 <= c.clock.sec <= last + 1 for c in clocks), clocks[:3]
    assert sum((s.header.stamp.sec, s.header.stamp.nanosec) in recorded for s in heard) >= 3
