"""foxglove_bridge driven by the ecosystem's client: @foxglove/ws-protocol (npm) in Node.

The same scenario runs once offering only `foxglove.websocket.v1` (Lichtblick's subprotocol,
served by our websockets layer) and once only `foxglove.sdk.v1` (Foxglove's, served by the
foxglove-sdk server), both on the bridge's one port. What the client sees is checked against
a real turtlesim: poses from an rclpy probe, the canvas PNG, the parameter on the node.
"""

from __future__ import annotations

import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from geometry_msgs.msg import Twist
from PySide6.QtGui import QImage
from rcl_interfaces.msg import Parameter, ParameterType, ParameterValue
from rcl_interfaces.srv import GetParameters, SetParameters
from std_srvs.srv import Trigger
from turtlesim.msg import Pose

from ws_testing import Background, TestNode, collect_stamped, wait_until
from ws_testing.foxglove import Driver, needs_client

PROTOCOLS = ['foxglove.websocket.v1', 'foxglove.sdk.v1']
ASSETS = r'^package://turtlesim/(?:[-\w]+/)*[-\w.]+\.(?:xml|png)$'
POSE_SCHEMA = ('float32 x\nfloat32 y\nfloat32 theta\n\nfloat32 linear_velocity\n'
               'float32 angular_velocity')

pytestmark = needs_client


@pytest.fixture(scope='module')
def bridge(module_turtlesim, module_launch):
    process = module_launch('foxglove_bridge', 'foxglove_bridge', '--ros-args',
                            '-p', 'port:=0', '-p', f"asset_uri_allowlist:=['{ASSETS}']")
    port = int(process.wait_for_output(r'Server listening on port (\d+)', 20).group(1))
    yield process, f'ws://127.0.0.1:{port}'
    assert process.stop() == 0, process.output
    assert 'Traceback' not in process.output, process.output


@pytest.fixture(scope='module')
def module_probe(module_ros_env) -> Iterator[TestNode]:
    node = TestNode(int(module_ros_env['ROS_DOMAIN_ID']), 'foxglove_probe')
    yield node
    node.close()


@pytest.fixture(params=PROTOCOLS)
def client(request, bridge) -> Iterator[Driver]:
    driver = Driver(bridge[1], request.param)
    driver.wait(lambda e: e.get('event') == 'open', 'the connection')
    driver.wait(lambda e: e.get('event') == 'advertise' and any(
        c['topic'] == '/turtle1/pose' for c in e['channels']), 'the /turtle1/pose channel')
    driver.wait(lambda e: e.get('event') == 'advertiseServices'
                and '/turtle1/set_pen' in e['names'], 'the set_pen service')
    driver.subprotocol = request.param
    yield driver
    driver.close()


def test_channels_carry_the_full_ros2msg_schema_and_cdr(client):
    assert client.of('open')[0]['protocol'] == client.subprotocol
    channels = {c['topic']: c for e in client.of('advertise') for c in e['channels']}
    pose = channels['/turtle1/pose']
    assert (pose['encoding'], pose['schemaName'], pose['schemaEncoding']) == (
        'cdr', 'turtlesim/msg/Pose', 'ros2msg')
    assert pose['schema'] == POSE_SCHEMA
    # Dependencies follow the type's own text, as upstream concatenates them.
    cmd_vel = channels['/turtle1/cmd_vel']['schema']
    assert cmd_vel.startswith('# This expresses velocity in free space')
    assert '=' * 80 + '\nMSG: geometry_msgs/Vector3\n' in cmd_vel

    client.send('subscribe', topic='/turtle1/pose')
    client.wait(lambda e: len(client.of('message')) >= 10, 'ten poses')
    message = client.of('message')[0]['message']
    assert set(message) == {'x', 'y', 'theta', 'linear_velocity', 'angular_velocity'}
    assert 0.0 < message['x'] < 11.1 and 0.0 < message['y'] < 11.1


def drive(client: Driver, twist: dict[str, Any], seconds: float) -> None:
    channel = client.send('advertise', topic='/turtle1/cmd_vel',
                          schemaName='geometry_msgs/msg/Twist')['channelId']
    time.sleep(1.0)  # DDS matches the bridge's new publisher with turtlesim
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        client.send('publish', channelId=channel, message=twist)
        time.sleep(0.1)


def test_published_cmd_vel_moves_the_turtle(client, module_probe):
    poses = collect_stamped(module_probe, Pose, '/turtle1/pose')
    with Background(module_probe):
        wait_until(lambda: poses, 10, 'the probe hearing /turtle1/pose')
        start = poses[-1][1]
        drive(client, {'linear': {'x': 1.5, 'y': 0, 'z': 0},
                       'angular': {'x': 0, 'y': 0, 'z': 0.5}}, 1.5)
        time.sleep(0.3)
    moved = max(abs(p.x - start.x) + abs(p.y - start.y) for _, p in poses)
    assert moved > 0.5, f'turtle moved only {moved:.2f} m'
    assert any(abs(p.linear_velocity - 1.5) < 1e-3 for _, p in poses)


PEN = {'foxglove.websocket.v1': (255, 0, 255), 'foxglove.sdk.v1': (255, 255, 0)}


def count_colour(png: str, rgb: tuple[int, int, int]) -> int:
    image = QImage(png).convertToFormat(QImage.Format.Format_RGB888)
    data, stride = bytes(image.constBits()), image.bytesPerLine()
    target = bytes(rgb)
    return sum(data[y * stride: y * stride + 3 * image.width()][x:x + 3] == target
               for y in range(image.height()) for x in range(0, 3 * image.width(), 3))


def test_set_pen_service_changes_the_canvas_colour(client, module_probe):
    r, g, b = PEN[client.subprotocol]
    call = client.send('call', service='/turtle1/set_pen',
                       request={'r': r, 'g': g, 'b': b, 'width': 6, 'off': 0})
    answer = client.wait(lambda e: e.get('callId') == call['callId'] and e['event'] in (
        'serviceCallResponse', 'serviceCallFailure'), 'the set_pen answer')
    assert answer['event'] == 'serviceCallResponse', answer
    assert answer['response'] == {}
    drive(client, {'linear': {'x': 1.0, 'y': 0, 'z': 0},
                   'angular': {'x': 0, 'y': 0, 'z': 1.0}}, 1.2)
    png = module_probe.call(Trigger, '/turtlesim/_save_canvas', Trigger.Request()).message
    assert count_colour(png, (r, g, b)) > 50


BACKGROUND_R = {'foxglove.websocket.v1': 120, 'foxglove.sdk.v1': 130}


def test_background_r_is_set_and_read_back(client, module_probe):
    value = BACKGROUND_R[client.subprotocol]
    name = '/turtlesim.background_r'
    client.send('subscribeParameterUpdates', names=[name])
    client.send('setParameters', parameters=[{'name': name, 'value': value}], id='set')
    # An update from the subscription (no request id), not only the reply to our set.
    client.wait(lambda e: e.get('event') == 'parameterValues' and e.get('id') is None and any(
        p['name'] == name and p['value'] == value for p in e['parameters']),
        'the parameter update')
    since = len(client.events)
    client.send('getParameters', names=[name], id='get')
    got = client.wait(lambda e: e.get('event') == 'parameterValues' and e.get('id') == 'get',
                      'the read-back', since=since)
    assert got['parameters'] == [{'name': name, 'value': value}]
    reply = module_probe.call(GetParameters, '/turtlesim/get_parameters',
                              GetParameters.Request(names=['background_r']))
    assert reply.values[0].integer_value == value
    # Changed by someone else (an rclpy client): the subscribed client hears of it.
    since = len(client.events)
    changed = Parameter(name='background_r', value=ParameterValue(
        type=ParameterType.PARAMETER_INTEGER, integer_value=value + 1))
    result = module_probe.call(SetParameters, '/turtlesim/set_parameters',
                               SetParameters.Request(parameters=[changed]))
    assert result.results[0].successful
    client.wait(lambda e: e.get('event') == 'parameterValues' and e['parameters'] == [
        {'name': name, 'value': value + 1}], 'the update after an rclpy set', since=since)


def errors_since(client: Driver, since: int) -> list[str]:
    return [e['message'] for e in client.events[since:]
            if e.get('event') in ('status', 'serviceCallFailure')]


def test_bad_input_gets_an_error_and_changes_nothing(client, module_probe, bridge):
    commands = collect_stamped(module_probe, Twist, '/turtle1/cmd_vel')
    poses = collect_stamped(module_probe, Pose, '/turtle1/pose')
    cases = [
        ('subscribeId', {'channelId': 99999}),                       # unknown channel id
        ('rawText', {'text': '{"op": "subscribe", "subscriptions": [{'}),  # malformed JSON
        ('rawText', {'text': '{"op": "noSuchOp"}'}),                  # unknown operation
        ('advertise', {'topic': '/turtle1/cmd_vel', 'schemaName': 'geometry_msgs/msg/Twist',
                       'encoding': 'protobuf'}),                      # wrong encoding
        ('publishBytes', {'channelId': 4242, 'hex': '00010000'}),     # unadvertised channel
        ('callServiceId', {'serviceId': 99999}),                      # unknown service id
    ]
    with Background(module_probe):
        for op, fields in cases:
            since = len(client.events)
            client.send(op, **fields)
            client.wait(lambda _e, since=since: errors_since(client, since),
                        f'an error status for {op} {fields}', since=since)
        # Garbage that is not a Twist, on a properly advertised cmd_vel channel.
        channel = client.send('advertise', topic='/turtle1/cmd_vel',
                              schemaName='geometry_msgs/msg/Twist')['channelId']
        since = len(client.events)
        client.send('publishBytes', channelId=channel, hex='0001000005')
        client.wait(lambda _e: errors_since(client, since), 'an error for a truncated Twist',
                    since=since)
        # A flood of subscribe/unsubscribe pairs, then one that stays.
        pose_channel = next(c['id'] for e in client.of('advertise') for c in e['channels']
                            if c['topic'] == '/turtle1/pose')
        for _ in range(200):
            sub = client.send('subscribeId', channelId=pose_channel)['subscriptionId']
            client.send('unsubscribe', subscriptionId=sub)
        wait_for_no_bridge_reader(module_probe)
        before = len(client.of('message'))
        client.send('subscribe', topic='/turtle1/pose')
        client.wait(lambda _e: len(client.of('message')) >= before + 10, 'poses after the flood')
        time.sleep(0.5)
    assert commands == [], 'bad input reached /turtle1/cmd_vel'
    assert poses, 'turtlesim stopped publishing'
    assert bridge[0].popen.poll() is None
    assert 'Traceback' not in bridge[0].output


def wait_for_no_bridge_reader(probe: TestNode) -> None:
    def readers() -> int:
        return sum(info.node_name == 'foxglove_bridge'
                   for info in probe.node.get_subscriptions_info_by_topic('/turtle1/pose'))
    deadline = time.monotonic() + 10
    while readers() and time.monotonic() < deadline:
        time.sleep(0.1)
    assert readers() == 0, 'the bridge still reads /turtle1/pose with no client subscribed'


@pytest.mark.parametrize('subprotocol', PROTOCOLS)
def test_oversized_message_is_refused_and_the_bridge_keeps_serving(subprotocol, bridge):
    big = Driver(bridge[1], subprotocol)
    try:
        big.wait(lambda e: e.get('event') == 'open', 'the connection')
        big.send('rawBinary', hex='01' + '00' * 1024, repeat=17 * 1024)  # 17 MiB
        big.wait(lambda e: e.get('event') == 'close', 'the connection closed', timeout=20)
        # websockets sends close 1009 (message too big), the SDK's server drops the connection;
        # a client still sending when the socket closes may see the reset (1006) first.
        assert big.of('close')[0]['code'] in (1009, 1006)
    finally:
        big.close()
    again = Driver(bridge[1], subprotocol)
    try:
        again.wait(lambda e: e.get('event') == 'advertise', 'channels after the oversized one')
    finally:
        again.close()


def test_launch_file_starts_the_bridge_with_upstreams_arguments(launch):
    process = launch(argv=['ros2', 'launch', 'foxglove_bridge', 'foxglove_bridge_launch.xml',
                           'port:=0', "topic_whitelist:=['/turtle1/.*']"])
    process.wait_for_output(r'\[foxglove_bridge[-\d]*\]: Server listening on port \d+', 20)
    assert process.stop() == 0, process.output
    assert 'Traceback' not in process.output, process.output


def test_connection_graph_names_turtlesim_as_the_pose_publisher(client):
    client.send('subscribeConnectionGraph')
    update = client.wait(lambda e: e.get('event') == 'connectionGraphUpdate' and any(
        t['name'] == '/turtle1/pose' for t in e['publishedTopics']), 'a graph with the pose')
    pose = next(t for t in update['publishedTopics'] if t['name'] == '/turtle1/pose')
    assert '/turtlesim' in pose['publisherIds']
    spawn = [s for s in update['advertisedServices'] if s['name'] == '/spawn']
    assert spawn and '/turtlesim' in spawn[0]['providerIds']


def test_assets_only_through_the_allowlist(client):
    from ament_index_python import get_package_share_directory
    package_xml = Path(get_package_share_directory('turtlesim')) / 'package.xml'
    cases = {1: ('package://turtlesim/package.xml', 0),          # allowed, present
             2: ('package://turtlesim/missing.png', 1),          # allowed, absent
             3: ('package://turtlesim/../turtlesim/package.xml', 1),  # not allowed
             4: ('file:///etc/passwd', 1)}                        # not allowed
    for request_id, (uri, _status) in cases.items():
        client.send('fetchAsset', uri=uri, requestId=request_id)
    for request_id, (uri, status) in cases.items():
        answer = client.wait(lambda e, rid=request_id: e.get('event') == 'fetchAssetResponse'
                             and e['requestId'] == rid, f'the answer for {uri}')
        assert answer['status'] == status, answer
        if status == 0:
            assert answer['size'] == package_xml.stat().st_size


@pytest.mark.parametrize('subprotocol', PROTOCOLS)
def test_sim_time_reaches_the_client_from_clock(subprotocol, launch):
    sim = launch('turtlesim', 'turtlesim_node', '--headless', '--fixed-step')
    sim.wait_for_output(r'Spawning turtle \[turtle1\]')
    bridge = launch('foxglove_bridge', 'foxglove_bridge', '--ros-args', '-p', 'port:=0',
                    '-p', 'use_sim_time:=true')
    port = bridge.wait_for_output(r'Server listening on port (\d+)', 20).group(1)
    driver = Driver(f'ws://127.0.0.1:{port}', subprotocol)
    try:
        info = driver.wait(lambda e: e.get('event') == 'serverInfo', 'serverInfo')['info']
        assert 'time' in info['capabilities']
        driver.wait(lambda _e: len(driver.of('time')) >= 5, 'five /clock times')
        stamps = [e['timestamp'] for e in driver.of('time')]
        assert stamps == sorted(stamps)
        # Simulated time: it starts near zero, not at the wall clock.
        assert stamps[-1] < 3600 * 10**9
        # Ctrl-C with a client still connected: exit 0, no traceback.
        assert bridge.stop() == 0, bridge.output
        assert 'Traceback' not in bridge.output and 'Error' not in bridge.output, bridge.output
    finally:
        driver.close()


def test_spawn_service_answers_and_the_new_turtle_gets_a_channel(client):
    name = 'fox_' + client.subprotocol.split('.')[1]  # fox_websocket / fox_sdk
    call = client.send('call', service='/spawn',
                       request={'x': 2.0, 'y': 2.0, 'theta': 0.0, 'name': name})
    answer = client.wait(lambda e: e.get('callId') == call['callId'] and e['event'] in (
        'serviceCallResponse', 'serviceCallFailure'), 'the spawn answer')
    assert answer == {'event': 'serviceCallResponse', 'callId': call['callId'],
                      'response': {'name': name}}
    client.wait(lambda e: e.get('event') == 'advertise' and any(
        c['topic'] == f'/{name}/pose' for c in e['channels']), f'the /{name}/pose channel')
