"""The Foxglove bridge beside the simulation (`diffbot_sim.launch.py` and `foxglove_bridge`, as
docs/simulation.md has the learner start them): a Lichtblick-protocol client sees the
simulator's topics advertised with their ros2msg schemas and decodes a live /scan whose centre
ray hits the room's red box, 1.35 m ahead of the lidar."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from support import RosProcess
from ws_testing.foxglove import Driver, needs_client

pytestmark = needs_client  # the foxglove client (node, npm)

# Per topic: its type and a line of that type's own text, or of a type it embeds.
SCHEMAS = {
    '/scan': ('sensor_msgs/msg/LaserScan', 'float32[] ranges'),
    '/odom': ('nav_msgs/msg/Odometry', 'MSG: geometry_msgs/PoseWithCovariance'),
    '/tf': ('tf2_msgs/msg/TFMessage', 'geometry_msgs/TransformStamped[] transforms'),
    '/camera/image_raw': ('sensor_msgs/msg/Image', 'uint8[] data'),
}


def test_bridge_carries_the_simulators_topics(tmp_path: Path, ros_env) -> None:
    bringup = RosProcess(['ros2', 'launch', 'diffbot_bringup', 'diffbot_sim.launch.py',
                          'rviz:=false'], ros_env, tmp_path / 'launch.log')
    bridge = RosProcess(['ros2', 'run', 'foxglove_bridge', 'foxglove_bridge', '--ros-args',
                         '-p', 'port:=0', '-p', 'use_sim_time:=true'], ros_env,
                        tmp_path / 'bridge.log')
    driver = None
    try:
        port = bridge.wait_for_output(r'Server listening on port (\d+)', 20).group(1)
        bringup.wait_for_output(r'\[mujoco_sim-1\] .*Loaded world', timeout=30)
        driver = Driver(f'ws://127.0.0.1:{port}', 'foxglove.websocket.v1')

        def channels() -> dict:
            return {c['topic']: c for e in driver.of('advertise') for c in e['channels']}

        driver.wait(lambda _e: set(SCHEMAS) <= set(channels()), 'the simulator\'s channels',
                    timeout=15)
        for topic, (name, line) in SCHEMAS.items():
            channel = channels()[topic]
            assert (channel['encoding'], channel['schemaName'], channel['schemaEncoding']) == (
                'cdr', name, 'ros2msg'), channel
            # A line of the schema, maybe with upstream's trailing comment.
            assert re.search(rf'^{re.escape(line)}\b', channel['schema'], re.M), (
                topic, channel['schema'][:300])

        driver.send('subscribe', topic='/scan')
        scan = driver.wait(lambda e: e.get('event') == 'message' and e['topic'] == '/scan',
                           'a /scan message')['message']
        assert scan['header']['frame_id'] == 'lidar_link'
        # The client decodes float32[] into a Float32Array, which JSON writes as {"0": ...}.
        ranges = [scan['ranges'][str(i)] for i in range(len(scan['ranges']))]
        assert len(ranges) == 360
        assert ranges[180] == pytest.approx(1.35, abs=0.02)  # the red box's near face
        assert bridge.stop() == 0, bridge.output
        assert 'Traceback' not in bridge.output, bridge.output
    finally:
        if driver is not None:
            driver.close()
        bridge.stop()
        assert bringup.stop() == 0, bringup.output
