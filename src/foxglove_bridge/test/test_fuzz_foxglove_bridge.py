"""Generated input for foxglove_bridge's WebSocket protocol, on both subprotocols (Hypothesis).

One bridge serves the module. The fuzzing client sends each generated frame, then a sentinel
(a fetchAsset the allow-list refuses, which always gets its own answer) so that every case
is answered before the next: a case that is invalid by construction (malformed JSON, unknown
ops, truncated or unknown binary opcodes, unknown channel and call ids, wrong encodings,
bytes or JSON that do not fit the advertised type, megabyte-sized garbage) must get an error
status (or serviceCallFailure) or a closed connection; a known op with arbitrary fields may
also be accepted. All along a bystander client receives a heartbeat topic and must never be
disconnected, an rclpy probe on the attacked topic must receive nothing, and the bridge must
keep running without a traceback. FUZZ_BRIDGE_EXAMPLES and FUZZ_BRIDGE_SDK_EXAMPLES change
the counts.
"""

from __future__ import annotations

import collections
import json
import os
import struct
import threading
import time
from collections.abc import Iterator
from typing import Any

import pytest
from geometry_msgs.msg import Twist
from hypothesis import given, settings
from hypothesis import strategies as st
from std_msgs.msg import String
from websockets.exceptions import ConnectionClosed
from websockets.sync.client import ClientConnection, connect

from ws_testing import Background, TestNode
from ws_testing.fuzz import CI, short, unknown_interface

SDK = 'foxglove.sdk.v1'
PROTOCOLS = ['foxglove.websocket.v1', SDK]
# Cases per subprotocol: ours 2,000; foxglove-sdk's server answers each case about 3x slower
# (16 ms against 5 ms here), so 1,000 keep that test near 30 s: 3,000 for the bridge.
CASES = {'foxglove.websocket.v1': int(os.environ.get('FUZZ_BRIDGE_EXAMPLES', '2000')),
         'foxglove.sdk.v1': int(os.environ.get('FUZZ_BRIDGE_SDK_EXAMPLES', '1000'))}
TARGET = '/fuzz/cmd_vel'        # the topic the fuzzer attacks; the probe listens on it
HEARTBEAT = '/fuzz/heartbeat'   # the bystander's subscription, published by the probe
KNOWN_OPS = ['subscribe', 'unsubscribe', 'advertise', 'unadvertise', 'getParameters',
             'setParameters', 'subscribeParameterUpdates', 'unsubscribeParameterUpdates',
             'subscribeConnectionGraph', 'unsubscribeConnectionGraph', 'fetchAsset']
FIELDS = ['subscriptions', 'subscriptionIds', 'channels', 'channelIds', 'parameterNames',
          'parameters', 'id', 'requestId', 'uri', 'channelId', 'encoding', 'topic',
          'schemaName']
TWIST_CDR_SIZE = 4 + 6 * 8      # encapsulation header and six float64
ANSWER_BOUND = 10.0             # seconds for the sentinel's answer


json_values = st.recursive(
    st.none() | st.booleans() | st.integers(-2**70, 2**70)
    | st.floats(allow_nan=False, allow_infinity=False) | short(60),
    lambda inner: st.lists(inner, max_size=4)
    | st.dictionaries(st.sampled_from([*FIELDS, 'name', 'value', 'type', 'x']), inner,
                      max_size=4),
    max_leaves=6)


def _not_json(value: str) -> bool:
    try:
        json.loads(value)
    except ValueError:
        return True
    return False


def _advertise(channel_id: int, encoding: str, schema: str = 'geometry_msgs/msg/Twist',
               topic: str = TARGET) -> str:
    return json.dumps({'op': 'advertise', 'channels': [
        {'id': channel_id, 'topic': topic, 'encoding': encoding, 'schemaName': schema}]})


def _data(channel_id: int, payload: bytes) -> bytes:
    return b'\x01' + struct.pack('<I', channel_id) + payload


# Each case: (kind, frames to send, whether an error or a close is required).
malformed = st.text(max_size=300).filter(_not_json).map(
    lambda t: ('malformed JSON', [t], True))
not_an_op = st.one_of(
    json_values.filter(lambda v: not isinstance(v, dict)),
    st.dictionaries(st.sampled_from(FIELDS), json_values, max_size=3),
    st.builds(lambda v: {'op': v}, json_values.filter(lambda v: not isinstance(v, str))),
).map(lambda v: ('not an op', [json.dumps(v)], True))
unknown_op = st.builds(
    lambda op, rest: ('unknown op', [json.dumps({**rest, 'op': op})], True),
    short(40).filter(lambda op: op not in KNOWN_OPS),
    st.dictionaries(st.sampled_from(FIELDS), json_values, max_size=3))
# Known ops with arbitrary fields: may be accepted, must never break anything. Topics are
# kept off TARGET (a valid advertisement there would be a valid request to publish).
known_op = st.builds(
    lambda op, rest: ('known op, arbitrary fields', [json.dumps({**rest, 'op': op})], False),
    st.sampled_from(KNOWN_OPS),
    st.dictionaries(st.sampled_from(FIELDS), json_values, max_size=4))
# Parameters of a node that exists (the probe, which declares no 'p'), with any value and hint.
parameters = st.builds(
    lambda op, name, value, hint: ('parameters of a real node', [json.dumps(
        {'op': op, 'id': 'p', 'parameterNames': [name],
         'parameters': [{'name': name, 'value': value, 'type': hint}]})], False),
    st.sampled_from(['setParameters', 'getParameters', 'subscribeParameterUpdates']),
    st.sampled_from(['/fuzz_bridge_probe.p', '/fuzz_bridge_probe', '/foxglove_bridge.port',
                     '/fuzz_bridge_probe.', '.p', '/fuzz_bridge_probe.p.q']),
    json_values | st.integers(2**63 - 2, 2**80) | st.lists(st.integers(-2**70, 2**70)),
    st.sampled_from([None, 'byte_array', 'float64', 'float64_array', 'junk', 7]))
binary = st.one_of(
    st.builds(lambda op, rest: bytes([op]) + rest,
              st.integers(0, 255).filter(lambda op: op not in (1, 2)), st.binary(max_size=64)),
    st.builds(lambda rest: b'\x01' + rest, st.binary(max_size=4)),          # truncated header
    st.builds(lambda rest: b'\x02' + rest, st.binary(max_size=12)),         # truncated header
    st.builds(lambda cid, rest: _data(cid, rest),                           # unknown channel
              st.integers(1000, 2**32 - 1), st.binary(max_size=64)),
    st.builds(lambda sid, cid, enc, rest: b'\x02' + struct.pack('<III', sid, cid, len(enc))
              + enc + rest,                                                 # unknown service
              st.integers(10**6, 2**32 - 1), st.integers(0, 2**32 - 1),
              st.sampled_from([b'cdr', b'json', b'', b'\xff\xfe']), st.binary(max_size=32)),
).map(lambda frame: ('binary', [frame], True)) | st.just(('empty binary frame', [b''], True))
# Advertisements get a fresh channel id each (the SDK's server keeps a refused channel id).
wrong_encoding = st.builds(
    lambda enc: ('wrong encoding', [('advertise', enc, 'geometry_msgs/msg/Twist')], True),
    short(30).filter(lambda e: e not in ('cdr', 'json')))
unknown_schema = st.builds(
    lambda name: ('unknown schema', [('advertise', 'cdr', name)], True),
    st.one_of(short(60),
              st.from_regex(r'[a-z_]{1,12}/(msg/)?[A-Z][a-z]{1,12}', fullmatch=True)
              ).filter(unknown_interface))
# On a properly advertised TARGET channel (opened in the fixture): bytes too short for a
# Twist, and JSON that is no Twist (an unknown field or a value of the wrong type).
bad_cdr = st.binary(max_size=TWIST_CDR_SIZE - 1).map(
    lambda b: ('truncated CDR on the target', [('data', 'cdr', b)], True))
bad_json = st.one_of(
    st.dictionaries(short(20).filter(lambda k: k not in ('linear', 'angular')),
                    json_values, min_size=1, max_size=3),
    st.builds(lambda v: {'linear': {'x': v}},
              json_values.filter(lambda v: isinstance(v, (str, list, dict, bool)) or v is None)),
    json_values.filter(lambda v: not isinstance(v, dict)),
).map(lambda v: ('JSON that is no Twist on the target',
                 [('data', 'json', json.dumps(v).encode())], True))
huge = st.builds(
    lambda size, kind: ('huge', [('x' * size) if kind == 'text' else (b'\x07' * size)], True),
    st.sampled_from([256 * 1024, 1024 * 1024, 4 * 1024 * 1024]),
    st.sampled_from(['text', 'binary']))
cases = st.one_of(malformed, not_an_op, unknown_op, known_op, parameters, binary,
                  wrong_encoding, unknown_schema, bad_cdr, bad_json, huge)


def _error(message: Any) -> str | None:
    """The text of an error status or a serviceCallFailure; None for anything else."""
    if not isinstance(message, str):
        return None
    reply = json.loads(message)
    if (reply.get('op') == 'status' and reply.get('level') == 2) \
            or reply.get('op') == 'serviceCallFailure':
        return str(reply.get('message', ''))
    return None


class Client:
    """A fuzzing connection: sends a case and its sentinel, reads until the sentinel's answer."""

    def __init__(self, url: str, subprotocol: str) -> None:
        self.url, self.subprotocol = url, subprotocol
        self.sentinel = 0
        self.fresh_id = 1000
        self.connections = 0
        self.channels: dict[str, int] = {}
        self.open()

    def open(self) -> None:
        self.ws: ClientConnection = connect(self.url, subprotocols=[self.subprotocol],
                                            open_timeout=10, max_size=None).__enter__()
        self.connections += 1
        self.read_until(lambda m: isinstance(m, str) and json.loads(m)['op'] == 'serverInfo')
        # One channel per encoding on TARGET, advertised properly: the invalid payloads go there.
        for number, encoding in enumerate(('cdr', 'json')):
            self.ws.send(_advertise(500 + number, encoding))
            self.channels[encoding] = 500 + number
        self.ask()

    def read_until(self, done: Any) -> list[Any]:
        seen = []
        deadline = time.monotonic() + ANSWER_BOUND
        while True:
            message = self.ws.recv(timeout=max(0.01, deadline - time.monotonic()))
            seen.append(message)
            if done(message):
                return seen

    def ask(self) -> list[Any]:
        """Send the sentinel; every frame the server sent until its answer."""
        self.sentinel += 1
        number = self.sentinel
        self.ws.send(json.dumps({'op': 'fetchAsset', 'uri': f'fuzz://sentinel/{number}',
                                 'requestId': number}))
        return self.read_until(lambda m: isinstance(m, bytes) and len(m) >= 5 and m[0] == 4
                               and struct.unpack_from('<I', m, 1)[0] == number)

    def send(self, frames: list[Any], must_fail: bool) -> tuple[str, list[str]]:
        """('answered' | 'closed', the error messages the server sent for the case). A
        service call is answered on its own task: its failure may follow the sentinel's."""
        try:
            for frame in frames:
                if isinstance(frame, tuple) and frame[0] == 'data':
                    self.ws.send(_data(self.channels[frame[1]], frame[2]))
                elif isinstance(frame, tuple):
                    self.fresh_id += 1
                    self.ws.send(_advertise(self.fresh_id, frame[1], frame[2]))
                else:
                    self.ws.send(frame)
            replies = self.ask()
            errors = [e for e in map(_error, replies) if e is not None]
            if must_fail and not errors:
                errors = [_error(self.read_until(lambda m: _error(m) is not None)[-1])]
        except ConnectionClosed:
            self.ws.close()
            self.open()
            return 'closed', []
        return 'answered', errors


class Bystander(threading.Thread):
    """Another client, subscribed to the heartbeat throughout; notes any disconnection."""

    def __init__(self, url: str, subprotocol: str) -> None:
        super().__init__(daemon=True)
        self.ws = connect(url, subprotocols=[subprotocol], open_timeout=10).__enter__()
        self.received: list[float] = []
        self.closed: str | None = None
        self.stopping = False

    def run(self) -> None:
        subscribed = False
        try:
            while not self.stopping:
                try:
                    message = self.ws.recv(timeout=0.2)
                except TimeoutError:
                    continue
                if isinstance(message, bytes) and message[:1] == b'\x01':
                    self.received.append(time.monotonic())
                elif not subscribed and isinstance(message, str):
                    reply = json.loads(message)
                    for channel in reply.get('channels', []) if reply['op'] == 'advertise' else []:
                        if channel['topic'] == HEARTBEAT:
                            self.ws.send(json.dumps({'op': 'subscribe', 'subscriptions': [
                                {'id': 1, 'channelId': channel['id']}]}))
                            subscribed = True
        except ConnectionClosed as error:
            self.closed = repr(error)

    def stop(self) -> None:
        self.stopping = True
        self.join(timeout=5)
        self.ws.close()


@pytest.fixture(scope='module')
def bridge(module_launch, module_ros_env) -> Iterator[tuple[Any, str, TestNode, list[Twist]]]:
    probe = TestNode(int(module_ros_env['ROS_DOMAIN_ID']), 'fuzz_bridge_probe')
    attacked: list[Twist] = []
    probe.node.create_subscription(Twist, TARGET, attacked.append, 10)
    heartbeat = probe.node.create_publisher(String, HEARTBEAT, 10)
    probe.node.create_timer(0.05, lambda: heartbeat.publish(String(data='beat')))
    process = module_launch('foxglove_bridge', 'foxglove_bridge', '--ros-args', '-p', 'port:=0')
    port = int(process.wait_for_output(r'Server listening on port (\d+)', 20).group(1))
    try:
        with Background(probe):
            yield process, f'ws://127.0.0.1:{port}', probe, attacked
    finally:
        probe.close()
    assert process.stop() == 0, process.output
    assert 'Traceback' not in process.output, process.output


@pytest.mark.parametrize('subprotocol', PROTOCOLS)
def test_generated_frames_get_an_error_or_a_close_and_break_nothing(subprotocol, bridge):
    process, url, _probe, attacked = bridge
    bystander = Bystander(url, subprotocol)
    bystander.start()
    deadline = time.monotonic() + 20
    while not bystander.received and time.monotonic() < deadline:
        time.sleep(0.05)
    assert bystander.received, 'the bystander got no heartbeat before fuzzing'
    fuzzer = Client(url, subprotocol)
    counts: collections.Counter[str] = collections.Counter()
    started = time.monotonic()

    @settings(CI, max_examples=CASES[subprotocol])
    @given(case=cases)
    def check(case: tuple[str, list[Any], bool]) -> None:
        kind, frames, must_fail = case
        # foxglove-sdk's server (Rust, not ours) ignores an empty binary frame: no answer, no
        # effect (the sentinel behind it is answered as usual).
        must_fail = must_fail and not (kind == 'empty binary frame' and subprotocol == SDK)
        outcome, errors = fuzzer.send(frames, must_fail)
        counts[kind] += 1
        counts[outcome] += 1
        if must_fail:
            assert outcome == 'closed' or errors, f'{kind}: no error for {frames!r:.300}'
        assert process.popen.poll() is None, process.output[-3000:]

    try:
        check()
        beats_before = len(bystander.received)
        time.sleep(0.5)  # the heartbeat runs at 20 Hz: the bystander is still being served
        assert len(bystander.received) > beats_before, 'the bystander stopped receiving'
        assert bystander.closed is None, f'the bystander was disconnected: {bystander.closed}'
    finally:
        bystander.stop()
        fuzzer.ws.close()
    total = sum(counts[k] for k in ('answered', 'closed'))
    print(f'\n{subprotocol}: {total} cases in {time.monotonic() - started:.1f} s '
          f'({fuzzer.connections - 1} connections closed by the bridge), '
          f'bystander got {len(bystander.received)} heartbeats, 0 disconnections; '
          + ', '.join(f'{k} {v}' for k, v in sorted(counts.items())))
    assert total >= CASES[subprotocol]
    assert attacked == [], f'invalid input was published on {TARGET}: {attacked[:3]}'
    assert 'Traceback' not in process.output, process.output[-3000:]


def test_a_valid_publish_reaches_the_probe(bridge):
    """The control for the check above: the probe does receive what is validly published."""
    _, url, probe, attacked = bridge
    with connect(url, subprotocols=[PROTOCOLS[0]], open_timeout=10) as ws:
        ws.recv(timeout=10)
        ws.send(_advertise(1, 'json'))
        probe_deadline = time.monotonic() + 10
        while probe.node.count_publishers(TARGET) == 0 and time.monotonic() < probe_deadline:
            time.sleep(0.05)
        ws.send(_data(1, b'{"linear": {"x": 1.5}}'))
        deadline = time.monotonic() + 10
        while not attacked and time.monotonic() < deadline:
            time.sleep(0.05)
    assert [m.linear.x for m in attacked] == [1.5]
    attacked.clear()
