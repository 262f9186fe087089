"""tf2_ros.BufferClient against `ros2 run tf2_ros buffer_server`, over real DDS: the
server's node (`tf_buffer`) listens to /tf_static and answers the LookupTransform action
`tf2_buffer_server`; a lookup that fails raises upstream's exception with the server's
error text, one that waits is answered when the frame appears.
"""
from __future__ import annotations

import time

import pytest
import rclpy.time
from rclpy.duration import Duration
from tf2_py import LookupException, TimeoutException
from tf2_ros import BufferClient

from ws_testing import Background, wait_until

LATEST = rclpy.time.Time()


def static_publisher(launch, parent: str, child: str, x: str):
    process = launch(argv=['ros2', 'run', 'tf2_ros', 'static_transform_publisher', '--x', x,
                           '--frame-id', parent, '--child-frame-id', child])
    process.wait_for_output(r'Spinning until stopped', timeout=20)
    return process


@pytest.fixture
def client(launch, probe):
    server = launch(argv=['ros2', 'run', 'tf2_ros', 'buffer_server'])
    buffer_client = BufferClient(probe.node, 'tf2_buffer_server', check_frequency=10.0,
                                 timeout_padding=Duration(seconds=2.0))
    probe.spin_until(buffer_client.action_client.server_is_ready, 20, 'the buffer server')
    with Background(probe):
        yield buffer_client
    buffer_client.destroy()
    assert server.stop() == 0
    assert 'Traceback' not in server.output


def test_buffer_server_answers_lookups(launch, probe, client, ros_env) -> None:
    wait_until(lambda: ('tf_buffer', '/') in probe.node.get_node_names_and_namespaces(), 10,
               "the buffer server's node tf_buffer")
    static_publisher(launch, 'world', 'robot', '1.5')
    # Waited for on the server (timeout 10 s): answered as soon as /tf_static has arrived.
    found = client.lookup_transform('world', 'robot', LATEST, Duration(seconds=10))
    assert (found.header.frame_id, found.child_frame_id) == ('world', 'robot')
    assert found.transform.translation.x == 1.5
    assert client.can_transform('world', 'robot', LATEST)
    # The advanced API, through the fixed frame.
    full = client.lookup_transform_full('robot', LATEST, 'world', LATEST, 'world')
    assert full.transform.translation.x == -1.5

    # No such frame: the server's LOOKUP_ERROR, raised as upstream's LookupException.
    started = time.monotonic()
    with pytest.raises(LookupException, match='"nowhere" passed to lookupTransform argument '
                       'source_frame does not exist'):
        client.lookup_transform('world', 'nowhere', LATEST, Duration(seconds=0.5))
    assert 0.4 < time.monotonic() - started < 3.0  # the server waited its timeout, no longer
    assert not client.can_transform('world', 'nowhere', LATEST)


def test_buffer_client_refuses_what_upstream_refuses(probe) -> None:
    lonely = BufferClient(probe.node, 'no_server_here')
    with pytest.raises(TimeoutException, match=r'^The BufferServer is not ready\.$'):
        lonely.lookup_transform('a', 'b', LATEST)
    with pytest.raises(TypeError, match=r'^Must pass a rclpy\.time\.Time object\.$'):
        lonely.lookup_transform('a', 'b', 0.0)
    lonely.destroy()
