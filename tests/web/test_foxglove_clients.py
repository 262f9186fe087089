"""foxglove_bridge as Lichtblick 1.28.1 met it beside the simulation.

Lichtblick offers both subprotocols (and is served `foxglove.sdk.v1`), asks for all parameters
every 15 s, and a tab that navigates away drops its connection with data still in flight.
Before these tests the bridge asked every node in turn for its parameters, waited 3 s for each
node without parameter services (the RViz page's `/_rqt_web`, the `ros2` daemon's node) and
warned each time; and one closed tab printed about 510 'Broken pipe' lines.
"""

from __future__ import annotations

import asyncio
import json
import re
import time
from collections.abc import Callable
from pathlib import Path

import pytest
import websockets
from sensor_msgs.msg import Image

from rqt_browser import start_rqt
from support import Background, RosProcess, TestNode, ros2, wait_until
from ws_testing.foxglove import Driver, needs_client

pytestmark = needs_client  # the foxglove client (node, npm)

BOTH = 'foxglove.sdk.v1,foxglove.websocket.v1'  # offered together, as Lichtblick does
# What the SDK's server or a socket library prints when a client's connection ends badly.
DISCONNECT = re.compile(r'Broken pipe|Connection reset|Error (?:sending|receiving)|'
                        r'socket\.send\(\) raised|closing handshake')


def start_bridge(ros_env: dict[str, str], log: Path) -> tuple[RosProcess, str]:
    bridge = RosProcess(['ros2', 'run', 'foxglove_bridge', 'foxglove_bridge', '--ros-args',
                         '-p', 'port:=0'], ros_env, log)
    port = bridge.wait_for_output(r'Server listening on port (\d+)', 20).group(1)
    return bridge, f'ws://127.0.0.1:{port}'


def wait_for_parameter_services(driver: Driver, nodes: list[str]) -> None:
    """Until the bridge advertises the nodes' parameter services: its own graph, which decides
    whom a request for all parameters asks, has then met them (a fresh bridge knows nobody)."""
    wanted = {f'{node}/{kind}' for node in nodes for kind in ('list_parameters', 'get_parameters')}

    def advertised() -> set[str]:
        return {name for event in driver.events if event.get('event') == 'advertiseServices'
                for name in event['names']}

    wait_until(lambda: wanted <= advertised(), 15, f'the bridge to advertise {sorted(wanted)}')


def all_parameters(driver: Driver, request_id: str) -> tuple[float, list[dict]]:
    """(seconds to the answer, the parameters) of a request for all parameters."""
    started = time.monotonic()
    driver.send('getParameters', names=[], id=request_id)
    answer = driver.wait(lambda e: e.get('event') == 'parameterValues'
                         and e.get('id') == request_id, f'parameterValues {request_id}')
    return time.monotonic() - started, answer['parameters']


def test_all_parameters_beside_the_simulation_rviz_page_and_daemon(
        tmp_path: Path, domain: int, ros_env) -> None:
    bringup = RosProcess(['ros2', 'launch', 'diffbot_bringup', 'diffbot_sim.launch.py',
                          'rviz:=false'], ros_env, tmp_path / 'launch.log')
    probe = TestNode(domain)
    rqt = None
    bridge = None
    drivers: list[Driver] = []
    try:
        rqt, _ = start_rqt(ros_env, tmp_path / 'rqt_state')  # the RViz page's node, /_rqt_web
        assert ros2(ros_env, 'daemon', 'start').returncode == 0
        bringup.wait_for_output(r'\[robot_state_publisher-2\] .*Robot initialized', timeout=30)
        bridge, url = start_bridge(ros_env, tmp_path / 'bridge.log')
        expected = {'/_rqt_web', '/mujoco_sim', '/robot_state_publisher', '/foxglove_bridge'}

        def names() -> set[str]:
            return {f"{ns.rstrip('/')}/{n}" for n, ns in probe.node.get_node_names_and_namespaces()}

        probe.spin_until(lambda: expected <= names() and any(
            n.startswith('/_ros2cli_daemon') for n in names()), 20, f'{expected} and the daemon')
        with Background(probe):  # the probe answers its own parameter services meanwhile
            for offered, served in ((BOTH, 'foxglove.sdk.v1'),
                                    ('foxglove.websocket.v1', 'foxglove.websocket.v1')):
                driver = Driver(url, offered)
                drivers.append(driver)
                assert driver.wait(lambda e: e.get('event') == 'open', 'the connection')[
                    'protocol'] == served
                wait_for_parameter_services(driver, ['/mujoco_sim', '/robot_state_publisher'])
                seconds, parameters = all_parameters(driver, f'{served}-1')
                assert seconds < 1.0, (served, seconds, bridge.output)
                got = {p['name']: p['value'] for p in parameters}
                assert got['/robot_state_publisher.use_sim_time'] is True, sorted(got)
                assert '/mujoco_sim.use_sim_time' in got, sorted(got)
                assert not [n for n in got if n.startswith(('/_rqt_web.', '/_ros2cli'))]
                logged = bridge.output
                seconds, again = all_parameters(driver, f'{served}-2')
                assert seconds < 1.0, (served, seconds)
                assert len(again) == len(parameters)
                assert bridge.output == logged, bridge.output[len(logged):]
        assert not re.search(r'parameter|no answer', bridge.output, re.I), bridge.output
        assert bridge.stop() == 0, bridge.output
        assert 'Traceback' not in bridge.output, bridge.output
    finally:
        for driver in drivers:
            driver.close()
        if bridge is not None:
            bridge.stop()
        if rqt is not None:
            rqt.stop()
        probe.close()
        assert bringup.stop() == 0, bringup.output


async def _subscribe(url: str, subprotocol: str, stalled: Callable[[], bool] | None,
                     abort: bool = False) -> None:
    """Subscribe to /camera_big and read three frames. Then, given `stalled`, stop reading
    until `stalled()` (the bridge has frames queued for us) and drop the connection without a
    closing handshake (reset or FIN); else leave cleanly."""
    async with websockets.connect(url, subprotocols=[subprotocol], max_size=None,
                                  max_queue=1) as ws:
        assert ws.subprotocol == subprotocol
        channel = None
        while channel is None:
            message = json.loads(await asyncio.wait_for(ws.recv(), 10))
            if message.get('op') == 'advertise':
                channel = next((c['id'] for c in message['channels']
                                if c['topic'] == '/camera_big'), None)
        await ws.send(json.dumps({'op': 'subscribe',
                                  'subscriptions': [{'id': 1, 'channelId': channel}]}))
        frames = 0
        while frames < 3:
            frames += isinstance(await asyncio.wait_for(ws.recv(), 10), bytes)
        if stalled is None:
            return
        deadline = time.monotonic() + 20
        while not stalled() and time.monotonic() < deadline:
            await asyncio.sleep(0.05)
        (ws.transport.abort if abort else ws.transport.close)()


@pytest.mark.parametrize('abort', [True, False], ids=['reset', 'fin'])
@pytest.mark.parametrize('subprotocol', ['foxglove.sdk.v1', 'foxglove.websocket.v1'])
def test_a_dropped_subscriber_is_one_line_at_most(tmp_path: Path, domain: int, ros_env,
                                                  subprotocol: str, abort: bool) -> None:
    probe = TestNode(domain, 'camera_big')
    publisher = probe.node.create_publisher(Image, '/camera_big', 10)
    image = Image(height=480, width=640, encoding='rgb8', step=1920, data=bytes(640 * 480 * 3))
    published = []
    probe.node.create_timer(1 / 30, lambda: (publisher.publish(image), published.append(1)))
    bridge = None
    try:
        with Background(probe):
            bridge, url = start_bridge(ros_env, tmp_path / 'bridge.log')
            mark = 0

            def stalled() -> bool:
                return len(published) >= mark + 90  # 83 MB the client did not read

            async def run() -> None:
                nonlocal mark
                mark = len(published)
                await _subscribe(url, subprotocol, stalled, abort)
            asyncio.run(run())
            bridge.wait_for_output(r"Unsubscribing from topic '/camera_big'", 15)
            # A well-behaved client after it: its subscription and clean close mean the
            # bridge has finished with the dropped one (whose lines came before).
            asyncio.run(_subscribe(url, subprotocol, None))
            wait_until(lambda: bridge.output.count("Unsubscribing from topic '/camera_big'")
                       == 2, 15, 'the second client to leave')
        lines = [line for line in bridge.output.splitlines() if DISCONNECT.search(line)]
        assert len(lines) <= 1, '\n'.join(lines[:20]) + f'\n... {len(lines)} lines'
        assert bridge.stop() == 0, bridge.output
        assert 'Traceback' not in bridge.output, bridge.output
    finally:
        if bridge is not None:
            bridge.stop()
        probe.close()


def test_a_node_that_never_answers_is_logged_once_and_not_asked_again(
        tmp_path: Path, domain: int, ros_env) -> None:
    """A node with parameter services that does not answer them (here: a node nobody spins)
    costs the first request its 3 s limit and upstream's two lines, once; later requests skip
    it. A node that answers is asked every time."""
    stuck = TestNode(domain, 'stuck')
    answering = TestNode(domain, 'answering')
    answering.node.declare_parameter('speed', 2.5)
    bridge = None
    driver = None
    try:
        with Background(answering):
            bridge, url = start_bridge(ros_env, tmp_path / 'bridge.log')
            driver = Driver(url, BOTH)
            driver.wait(lambda e: e.get('event') == 'open', 'the connection')
            wait_until(lambda: {'/stuck', '/answering'} <= {
                f"{ns.rstrip('/')}/{n}"
                for n, ns in answering.node.get_node_names_and_namespaces()}, 10, 'the nodes')
            wait_for_parameter_services(driver, ['/stuck', '/answering'])
            seconds, parameters = all_parameters(driver, 'first')
            assert 2.5 < seconds < 5.0, seconds  # the stuck node's 3 s limit, not more
            assert {p['name']: p['value'] for p in parameters}['/answering.speed'] == 2.5
            bridge.wait_for_output(r'Adding node /stuck to the ignore list', 5)
            logged = bridge.output
            assert re.search(r"\[ERROR\] \[[\d.]+\] \[foxglove_bridge\]: Failed to retrieve "
                             r"parameters from node '/stuck': ", logged), logged
            seconds, again = all_parameters(driver, 'second')
            assert seconds < 1.0, seconds
            assert {p['name'] for p in again} == {p['name'] for p in parameters}
            assert bridge.output == logged, bridge.output[len(logged):]
        assert len([line for line in bridge.output.splitlines() if '/stuck' in line]) == 2, (
            bridge.output)
    finally:
        if driver is not None:
            driver.close()
        if bridge is not None:
            bridge.stop()
        answering.close()
        stuck.close()
