"""foxglove_bridge's origin policy: no page of another site drives the robot.

A page on another site (Origin: https://evil.example) or a DNS-rebinding page (Host:
evil.example:PORT, resolving to 127.0.0.1) opens a WebSocket from the learner's own browser,
with the handshake a browser sends, frames to advertise and publish /turtle1/cmd_vel right
behind it. Both subprotocols: the bridge answers HTTP 403, logs one line naming the
parameter, and an rclpy probe on /turtle1/cmd_vel receives nothing; a loopback page, the
hosted Foxglove and Lichtblick apps and a client without Origin get serverInfo, and the
loopback page's JSON-encoded Twist (upstream's second client encoding) reaches the probe.
"""

from __future__ import annotations

import base64
import json
import os
import socket
import struct
from collections.abc import Iterator

import pytest
from geometry_msgs.msg import Twist
from websockets.sync.client import connect

from ws_testing import TestNode, wait_until

PROTOCOLS = ['foxglove.websocket.v1', 'foxglove.sdk.v1']
ATTACK_X = 9.0   # what a refused page tries to publish
LOOPBACK_X = 0.5  # what the accepted loopback page publishes


@pytest.fixture(scope='module')
def bridge(module_launch):
    process = module_launch('foxglove_bridge', 'foxglove_bridge', '--ros-args', '-p', 'port:=0')
    port = int(process.wait_for_output(r'Server listening on port (\d+)', 20).group(1))
    yield process, port
    assert process.stop() == 0, process.output
    assert 'Traceback' not in process.output, process.output


@pytest.fixture(scope='module')
def cmd_vel(module_ros_env) -> Iterator[tuple[TestNode, list[Twist]]]:
    probe = TestNode(int(module_ros_env['ROS_DOMAIN_ID']), 'origin_probe')
    received: list[Twist] = []
    probe.node.create_subscription(Twist, '/turtle1/cmd_vel', received.append, 10)
    yield probe, received
    probe.close()


def advertise(encoding: str) -> str:
    return json.dumps({'op': 'advertise', 'channels': [
        {'id': 7, 'topic': '/turtle1/cmd_vel', 'encoding': encoding,
         'schemaName': 'geometry_msgs/msg/Twist'}]})


def publish_frame(payload: bytes) -> bytes:
    return b'\x01' + struct.pack('<I', 7) + payload


def masked(opcode: int, payload: bytes) -> bytes:
    """One client-to-server WebSocket frame (clients must mask, RFC 6455 5.3)."""
    mask = os.urandom(4)
    length = len(payload)
    head = bytes([0x80 | opcode])
    if length < 126:
        head += bytes([0x80 | length])
    else:
        head += bytes([0x80 | 126]) + struct.pack('>H', length)
    return head + mask + bytes(b ^ mask[i % 4] for i, b in enumerate(payload))


def browser_attack(port: int, subprotocol: str, origin: str | None, host: str) -> bytes:
    """A browser's upgrade request, then advertise + publish frames sent without waiting;
    returns all the server sent until it closed the connection."""
    lines = ['GET / HTTP/1.1', f'Host: {host}', 'Upgrade: websocket', 'Connection: Upgrade',
             f'Sec-WebSocket-Key: {base64.b64encode(os.urandom(16)).decode()}',
             'Sec-WebSocket-Version: 13', f'Sec-WebSocket-Protocol: {subprotocol}']
    if origin is not None:
        lines.append(f'Origin: {origin}')
    twist = json.dumps({'linear': {'x': ATTACK_X}}).encode()
    request = ('\r\n'.join(lines) + '\r\n\r\n').encode() + masked(1, advertise('json').encode()) \
        + masked(2, publish_frame(twist))
    received = b''
    with socket.create_connection(('127.0.0.1', port), timeout=10) as sock:
        try:
            sock.sendall(request)
        except OSError:
            pass  # refused before all of it was read: what we receive tells
        try:
            while chunk := sock.recv(65536):
                received += chunk
        except ConnectionResetError:
            pass
    return received


@pytest.mark.parametrize('subprotocol', PROTOCOLS)
def test_cross_site_and_rebinding_pages_are_refused_and_publish_nothing(subprotocol, bridge,
                                                                        cmd_vel):
    process, port = bridge
    probe, received = cmd_vel
    cases = [('https://evil.example', f'127.0.0.1:{port}', 'origin_allowlist'),
             ('http://evil.example:8000', f'localhost:{port}', 'origin_allowlist'),
             ('null', f'127.0.0.1:{port}', 'origin_allowlist'),   # a sandboxed page
             ('http://evil.example:' + str(port), f'evil.example:{port}', "'address'"),
             (None, f'evil.example:{port}', "'address'")]
    for origin, host, parameter in cases:
        mark = len(process.output)
        answer = browser_attack(port, subprotocol, origin, host)
        assert answer.startswith(b'HTTP/1.1 403 Forbidden\r\n'), (origin, host, answer[:300])
        assert parameter.encode() in answer, answer
        wait_until(lambda mark=mark: 'Refused' in process.output[mark:], 5, 'the log line')
        lines = [line for line in process.output[mark:].splitlines() if 'Refused' in line]
        assert len(lines) == 1 and '[WARN]' in lines[0] and parameter in lines[0], lines

    # The loopback page's own message shows the path works; the refused ones never came.
    origin = f'http://127.0.0.1:{port + 1}'
    with connect(f'ws://127.0.0.1:{port}', subprotocols=[subprotocol], origin=origin,
                 open_timeout=10) as page:
        info = json.loads(page.recv(timeout=10))
        assert info['op'] == 'serverInfo' and 'json' in info['supportedEncodings'], info
        page.send(advertise('json'))
        probe.spin_until(lambda: probe.node.count_publishers('/turtle1/cmd_vel') > 0, 10,
                         'the bridge advertising /turtle1/cmd_vel')
        page.send(publish_frame(json.dumps({'linear': {'x': LOOPBACK_X}}).encode()))
        probe.spin_until(lambda: any(m.linear.x == LOOPBACK_X for m in received), 10,
                         "the loopback page's Twist")
    probe.spin_for(0.3)
    assert [m.linear.x for m in received] == [LOOPBACK_X], 'a refused page published'
    received.clear()
    probe.spin_until(lambda: probe.node.count_publishers('/turtle1/cmd_vel') == 0, 10,
                     'the page\'s publisher to leave with it')


@pytest.mark.parametrize('subprotocol', PROTOCOLS)
@pytest.mark.parametrize('origin', [None, 'http://localhost:3000', 'http://[::1]:8080',
                                    'https://app.foxglove.dev',
                                    'https://lichtblick-suite.github.io'])
def test_loopback_pages_and_the_hosted_apps_are_accepted(subprotocol, origin, bridge):
    process, port = bridge
    mark = len(process.output)
    for host in ('127.0.0.1', 'localhost'):
        with connect(f'ws://{host}:{port}', subprotocols=[subprotocol], origin=origin,
                     open_timeout=10) as client:
            assert client.subprotocol == subprotocol
            info = json.loads(client.recv(timeout=10))
            assert info['op'] == 'serverInfo', info
    assert 'Refused' not in process.output[mark:]


@pytest.mark.parametrize('subprotocol', PROTOCOLS)
def test_json_that_does_not_fit_the_type_gets_an_error_naming_the_field(subprotocol, bridge,
                                                                        cmd_vel):
    _, port = bridge
    probe, received = cmd_vel
    with connect(f'ws://127.0.0.1:{port}', subprotocols=[subprotocol], open_timeout=10) as c:
        c.recv(timeout=10)
        c.send(advertise('json'))
        probe.spin_until(lambda: probe.node.count_publishers('/turtle1/cmd_vel') > 0, 10,
                         'the bridge advertising /turtle1/cmd_vel')
        for payload, words in ((b'{"linear": {"x": "fast"}}', "'linear.x' must be a number"),
                               (b'{"linar": {}}', "'linar' is not a field"),
                               (b'[1, 2', 'not valid JSON')):
            c.send(publish_frame(payload))
            while True:
                message = c.recv(timeout=10)
                if isinstance(message, str) and json.loads(message).get('op') == 'status':
                    break
            assert words in json.loads(message)['message'], message
    probe.spin_for(0.3)
    assert received == []
