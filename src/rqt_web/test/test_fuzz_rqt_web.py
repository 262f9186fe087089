"""Generated input for the rqt web app's JSON API, the RViz page's endpoints and its WebSocket.

One rqt server (with its token) serves the module. Each generated request is invalid by
construction (a body that is no JSON or no object, unknown interface types, values that do
not fit, invalid topic, node and frame names, unknown tools, non-finite numbers, unknown
WebSocket ops); it must get an error answer: a 4xx status, or 200 with an `error` field
(the JSON API's way), never a 5xx or a dropped connection. Meanwhile a bystander polls
/api/ping and must always be answered; an rclpy probe on the topics the requests aim at
must receive nothing; the server must keep running without a traceback.
FUZZ_RQT_EXAMPLES changes the count.
"""

from __future__ import annotations

import collections
import http.client
import json
import math
import os
import threading
import time
import urllib.parse
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from geometry_msgs.msg import PointStamped, PoseStamped, PoseWithCovarianceStamped, Twist
from hypothesis import given, settings
from hypothesis import strategies as st
from websockets.sync.client import connect

from ws_testing import Background, TestNode, leased_domain, ros_environment
from ws_testing.browser import start_rqt
from ws_testing.fuzz import CI, short, unknown_interface

CASES = int(os.environ.get('FUZZ_RQT_EXAMPLES', '2000'))
TARGETS = {'/turtle1/cmd_vel': Twist, '/initialpose': PoseWithCovarianceStamped,
           '/goal_pose': PoseStamped, '/clicked_point': PointStamped}
# Names no ROS name can be: each ends with a character (pair) names may not contain.
bad_names = st.builds(lambda a, bad: a + bad, short(20),
                      st.sampled_from([' ', '!', '?', '%', '-', '.', '\u00e9', '//', '~x']))
bad_topics = bad_names.map(lambda n: '/' + n)
bad_types = st.one_of(
    short(60),
    st.builds(lambda package, kind, name: f'{package}/{kind}/{name}',
              st.sampled_from(['std_msgs', 'geometry_msgs', 'turtlesim', 'std_srvs', 'nope']),
              st.sampled_from(['msg', 'srv', 'action']), short(12)),
    st.sampled_from(['geometry_msgs/msg/Nope', 'std_srvs/srv/Trigger/x', '/', 'std_msgs',
                     'msg/String', '../../etc/passwd'])).filter(unknown_interface)
json_values = st.recursive(
    st.none() | st.booleans() | st.integers(-2**70, 2**70) | st.floats()
    | short(40),
    lambda inner: st.lists(inner, max_size=3) | st.dictionaries(short(10),
                                                                 inner, max_size=3),
    max_leaves=6)
not_twist = st.one_of(
    st.builds(lambda v: {'linear': {'x': v}},
              json_values.filter(lambda v: not isinstance(v, (int, float)) or isinstance(v, bool))),
    st.dictionaries(short(12).filter(lambda k: k not in ('linear', 'angular')),
                    json_values, min_size=1, max_size=3),
    json_values.filter(lambda v: not isinstance(v, dict) and v is not None))
not_json_body = st.binary(max_size=200).filter(lambda b: not _is_json(b))
not_object = json_values.filter(lambda v: not isinstance(v, dict)).map(json.dumps)
POSTS = ['/api/service/call', '/api/topic/publish', '/api/parameters/set', '/api/rviz/tool']


def _is_json(data: bytes) -> bool:
    try:
        json.loads(data)
    except ValueError:
        return False
    return True


def _post(path: str, body: Any) -> tuple[str, str, bytes]:
    return 'POST', path, body if isinstance(body, bytes) else json.dumps(body).encode()


def _get(route: str, **query: Any) -> tuple[str, str, bytes]:
    return 'GET', f'{route}?{urllib.parse.urlencode(query)}', b''


finite = st.floats(-1e6, 1e6)
requests = st.one_of(
    st.builds(lambda path, body: ('body is no JSON', _post(path, body)),
              st.sampled_from(POSTS), not_json_body),
    st.builds(lambda path, body: ('body is no object', _post(path, body.encode())),
              st.sampled_from(POSTS), not_object),
    st.builds(lambda kind, values: ('publish: no such type', _post(
        '/api/topic/publish', {'topic': '/turtle1/cmd_vel', 'type': kind, 'values': values})),
        bad_types, json_values),
    st.builds(lambda values: ('publish: values that are no Twist', _post(
        '/api/topic/publish', {'topic': '/turtle1/cmd_vel', 'type': 'geometry_msgs/msg/Twist',
                               'values': values})), not_twist),
    st.builds(lambda topic: ('publish: invalid topic', _post(
        '/api/topic/publish', {'topic': topic, 'type': 'geometry_msgs/msg/Twist',
                               'values': {}})), bad_topics),
    st.builds(lambda name, kind, timeout: ('call: bad type or timeout', _post(
        '/api/service/call', {'name': name, 'type': kind, 'timeout': timeout, 'values': {}})),
        st.one_of(bad_names, st.just('/clear')), bad_types,
        st.one_of(st.just(1.0), st.floats(), json_values)),
    st.builds(lambda timeout: ('call: timeout out of range', _post(
        '/api/service/call', {'name': '/clear', 'type': 'std_srvs/srv/Empty', 'timeout': timeout})),
        st.one_of(st.floats().filter(lambda t: not 0 < t <= 60), st.booleans(), short(20))),
    st.builds(lambda node, name, value: ('set parameter: invalid node', _post(
        '/api/parameters/set', {'node': node, 'name': name, 'value': value})),
        bad_names, short(30), json_values),
    st.builds(lambda node: ('parameters: invalid node', _get('/api/parameters', node=node)),
              bad_names),
    st.builds(lambda kind, part, which: ('interface: no such type', _get(
        '/api/interface', type=kind, kind=which, part=part)),
        bad_types, short(10), st.sampled_from(['msg', 'srv', 'action', 'x'])),
    st.builds(lambda tool, topic, frame, x, y, yaw: ('tool: invalid', _post(
        '/api/rviz/tool', {'tool': tool, 'topic': topic, 'frame': frame, 'x': x, 'y': y,
                           'yaw': yaw})),
        st.one_of(st.sampled_from(['initialpose', 'goal', 'point']), short(12)),
        st.one_of(st.none(), bad_topics, st.just('relative/topic')),
        st.one_of(st.just('map'), st.just(''), short(20)),
        st.one_of(finite, st.floats(), json_values, st.integers(10**308, 10**400)),
        finite, finite).filter(lambda case: _invalid_tool(json.loads(case[1][2]))),
    st.builds(lambda topic, kind: ('markers: invalid', _get(
        '/api/rviz/markers', topic=topic, type=kind)),
        st.one_of(bad_topics, short(30), st.just('/' + 'a' * 300)),
        st.one_of(st.sampled_from(['Marker', 'MarkerArray']), short(12))
    ).filter(lambda case: not _valid_markers(case[1][1])),
    st.builds(lambda topic, kind: ('latest: invalid', _get(
        '/api/rviz/latest', topic=topic, type=kind)),
        st.one_of(bad_topics, short(30)),
        st.one_of(st.just('nav_msgs/msg/Path'), bad_types)),
    st.builds(lambda topic: ('description: invalid topic', _get(
        '/api/rviz/description', topic=topic)),
        st.one_of(bad_topics, short(30).filter(lambda t: not t.startswith('/')))),
    st.builds(lambda kind, topic, after: ('stream: invalid', _get(
        f'/api/rviz/{kind}', topic=topic, after=after)),
        st.sampled_from(['cloud', 'image']), st.one_of(bad_topics, st.just('relative')),
        st.one_of(st.just('0'), short(8))),
    st.builds(lambda path: ('config: not an .rviz file', _get('/api/rviz/config', path=path)),
              short(80).filter(lambda p: not p.endswith('.rviz'))),
    st.builds(lambda uri: ('resource: not servable', _get('/api/rviz/resource', uri=uri)),
              st.one_of(short(80), st.just('file:///etc/passwd'),
                        st.just('package://nope/x.stl'), st.just('package://turtlesim/../../x'))),
    st.builds(lambda frame, fixed: ('tf lookup: invalid frame', _get(
        '/api/tf/lookup', frame=frame, fixed_frame=fixed)),
        st.one_of(st.just(''), st.just('f' * 300)), short(20)),
    st.builds(lambda after: ('tf poses: after is no integer', _get('/api/tf/poses', after=after)),
              short(10).filter(lambda t: not _is_int(t))),
)


def _is_int(value: str) -> bool:
    try:
        int(value)
    except ValueError:
        return False
    return True


def _invalid_tool(body: dict) -> bool:
    """Whether rviz's tool endpoint must refuse `body` (its own rules, written out)."""
    def number(value: Any) -> bool:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            return False
        try:
            return math.isfinite(float(value))
        except OverflowError:
            return False
    topic = body.get('topic')
    return not (body.get('tool') in ('initialpose', 'goal', 'point')
                and all(number(body.get(k)) for k in ('x', 'y', 'yaw'))
                and isinstance(body.get('frame'), str) and 0 < len(body['frame']) <= 256
                and (topic is None or forms_topic_ok(topic)))


def forms_topic_ok(topic: Any) -> bool:
    from rclpy.validate_full_topic_name import validate_full_topic_name
    try:
        validate_full_topic_name(str(topic))
    except Exception:
        return False
    return True


def _valid_markers(path: str) -> bool:
    query = urllib.parse.parse_qs(urllib.parse.urlparse(path).query)
    topic = query.get('topic', [''])[0]
    return topic.startswith('/') and len(topic) <= 256 and query.get('type', [''])[0] in (
        'Marker', 'MarkerArray') and all(c.isalnum() or c in '/_' for c in topic)


ws_messages = st.one_of(
    not_json_body.map(lambda b: ('ws: no JSON', b.decode('latin-1'))),
    not_object.map(lambda m: ('ws: no object', m)),
    st.builds(lambda op, rest: ('ws: unknown op', json.dumps({**rest, 'op': op})),
              st.one_of(short(20), json_values).filter(
                  lambda op: op not in ('graph', 'console', 'canvas', 'uncanvas', 'teleop',
                                        'monitor', 'unmonitor', 'goal', 'cancel')),
              st.dictionaries(short(10), json_values, max_size=2)),
    st.builds(lambda topic, key: ('ws: teleop without an arrow key', json.dumps(
        {'op': 'teleop', 'topic': topic, 'key': key})),
        st.one_of(st.just('/turtle1/cmd_vel'), bad_topics), json_values.filter(
            lambda k: k not in ('ArrowUp', 'ArrowDown', 'ArrowLeft', 'ArrowRight'))),
    st.builds(lambda kind: ('ws: monitor of no type', json.dumps(
        {'op': 'monitor', 'topic': '/turtle1/pose', 'type': kind})), bad_types),
    st.builds(lambda kind, values: ('ws: goal of no type', json.dumps(
        {'op': 'goal', 'id': 'g', 'action': '/turtle1/rotate_absolute', 'type': kind,
         'values': values})), bad_types, json_values),
)


class Bystander(threading.Thread):
    """Polls /api/ping on its own connection; every failure is kept."""

    def __init__(self, port: int, token: str) -> None:
        super().__init__(daemon=True)
        self.port, self.token = port, token
        self.answered = 0
        self.failures: list[str] = []
        self.stopping = threading.Event()

    def run(self) -> None:
        connection = http.client.HTTPConnection('127.0.0.1', self.port, timeout=10)
        while not self.stopping.wait(0.05):
            try:
                connection.request('GET', '/api/ping', headers={'X-Rqt-Token': self.token})
                response = connection.getresponse()
                body = response.read()
                if response.status != 200 or not json.loads(body)['ok']:
                    self.failures.append(f'{response.status} {body[:200]!r}')
                self.answered += 1
            except (OSError, http.client.HTTPException, ValueError) as error:
                self.failures.append(repr(error))
                connection.close()
                connection = http.client.HTTPConnection('127.0.0.1', self.port, timeout=10)
        connection.close()


@pytest.fixture(scope='module')
def rqt(tmp_path_factory) -> Iterator[tuple[Any, TestNode, list[Any]]]:
    with leased_domain() as domain:
        server, _ = start_rqt(ros_environment(domain),
                              Path(tmp_path_factory.mktemp('fuzz-rqt')) / 'state')
        probe = TestNode(domain, 'fuzz_rqt_probe')
        published: list[Any] = []
        for topic, msg_type in TARGETS.items():
            probe.node.create_subscription(msg_type, topic, published.append, 10)
        try:
            with Background(probe):
                yield server, probe, published
        finally:
            probe.close()
            server.stop()


def _answer(connection: http.client.HTTPConnection, token: str,
            request: tuple[str, str, bytes]) -> tuple[int, bytes]:
    method, path, body = request
    connection.request(method, path, body=body or None,
                       headers={'X-Rqt-Token': token, 'Content-Type': 'application/json'})
    response = connection.getresponse()
    return response.status, response.read()


def test_generated_requests_get_an_error_and_break_nothing(rqt):
    server, _probe, published = rqt
    bystander = Bystander(server.port, server.token)
    bystander.start()
    connection = http.client.HTTPConnection('127.0.0.1', server.port, timeout=30)
    ws = connect(f'ws://127.0.0.1:{server.port}/ws', open_timeout=10,
                 additional_headers={'X-Rqt-Token': server.token}).__enter__()
    counts: collections.Counter[str] = collections.Counter()
    started = time.monotonic()

    @settings(CI, max_examples=CASES)
    @given(case=st.one_of(requests, requests, requests, ws_messages))
    def check(case: tuple[str, Any]) -> None:
        kind, request = case
        counts[kind] += 1
        if kind.startswith('ws:'):
            ws.send(request)
            deadline = time.monotonic() + 10
            while True:
                reply = json.loads(ws.recv(timeout=max(0.01, deadline - time.monotonic())))
                if reply.get('op') == 'error':
                    return
        status, body = _answer(connection, server.token, request)
        assert status < 500, f'{kind}: {status} for {request!r:.300}: {body[:300]!r}'
        if status == 200:
            assert 'error' in json.loads(body), f'{kind}: accepted {request!r:.300}: {body[:300]!r}'
        else:
            assert 400 <= status < 500 and status != 403, (kind, status, body[:300])

    try:
        check()
        answered = bystander.answered
        time.sleep(0.3)
        assert bystander.answered > answered, 'the bystander is no longer answered'
    finally:
        bystander.stopping.set()
        bystander.join(timeout=15)
        connection.close()
        ws.close()
    total = sum(counts.values())
    print(f'\nrqt web: {total} cases in {time.monotonic() - started:.1f} s, bystander answered '
          f'{bystander.answered} pings, {len(bystander.failures)} failures; '
          + ', '.join(f'{k} {v}' for k, v in sorted(counts.items())))
    assert bystander.failures == [], bystander.failures[:5]
    assert published == [], f'refused requests published: {published[:3]}'
    assert total >= min(CASES, 2000)
    log = Path(server.env['RQT_WEB_STATE_DIR'])
    for path in log.glob('*.log'):
        assert 'Traceback' not in path.read_text(errors='replace'), path
