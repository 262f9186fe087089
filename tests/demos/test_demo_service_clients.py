"""The two How-to pages on calling services from rclpy, typed as written (their code in
tests/data):

"Using callback groups": the page's service node and client node. With both callback groups
None the client sends one request and never gets its answer (deadlock); with the page's fix
(a MutuallyExclusiveCallbackGroup each) and its other working configurations, a request and a
response every second; with one shared Mutually Exclusive group, the deadlock again.

"Synchronous vs. asynchronous service clients": the synchronous client with rclpy.spin in a
thread gets its sum; the same call made in a subscription callback never returns; the
call_async loop gets its sum.
"""
from __future__ import annotations

import os
import re
import signal
import sys
import time
from pathlib import Path

import pytest
from node_runtime.discovery import profile_path

DATA = Path(__file__).parents[1] / 'data'
LOG = r'^\[INFO\] \[[\d.]+\] '
DEFAULT = 'client_cb_group = None\n        timer_cb_group = None\n'
# (the page's two lines, whether the client gets its answers)
CONFIGURATIONS = {
    'default groups': (DEFAULT, False),
    'the fix': ('client_cb_group = MutuallyExclusiveCallbackGroup()\n'
                '        timer_cb_group = MutuallyExclusiveCallbackGroup()\n', True),
    'one shared exclusive group': ('client_cb_group = MutuallyExclusiveCallbackGroup()\n'
                                   '        timer_cb_group = client_cb_group\n', False),
    'one reentrant group': ('client_cb_group = ReentrantCallbackGroup()\n'
                            '        timer_cb_group = client_cb_group\n', True),
}
DEADLOCK_SECONDS = 3.5  # a working client has had three answers by then


@pytest.fixture(scope='module')
def page_env(module_ros_env):
    # The page's client sends its first request 1 s after it starts, without waiting for the
    # service; the server answers only once it has discovered the client (Fast DDS announces
    # a participant every 3 s by default, so on a loaded machine a first answer can be lost
    # and the call then waits for ever, as on any Jazzy). The workspace's 0.5 s announcement
    # profile, which a user may choose too, keeps the test about callback groups.
    return {**module_ros_env, 'FASTRTPS_DEFAULT_PROFILES_FILE': profile_path()}


@pytest.fixture(scope='module')
def service_node(module_launch, page_env):
    node = module_launch(argv=[sys.executable, str(DATA / 'callback_groups' / 'service_node.py')],
                         env=page_env)
    node.wait_for_output(LOG + r'\[service_node\]: Starting server node, shut down with CTRL-C$',
                         timeout=20)
    yield node
    node.stop()
    # The page's own Ctrl-C line.
    assert 'Keyboard interrupt, shutting down.' in node.output


def test_callback_groups(service_node, module_launch, page_env, tmp_path) -> None:
    page = (DATA / 'callback_groups' / 'client_node.py').read_text()
    assert DEFAULT in page
    clients = {}
    for name, (lines, _works) in CONFIGURATIONS.items():
        path = tmp_path / f"{name.replace(' ', '_').replace(',', '')}.py"
        path.write_text(page.replace(DEFAULT, lines))
        clients[name] = module_launch(argv=[sys.executable, str(path)], env=page_env)
    for client in clients.values():
        client.wait_for_output(LOG + r'\[client_node\]: Sending request$', timeout=20)
    started = time.monotonic()
    for name, (_lines, works) in CONFIGURATIONS.items():
        if works:
            clients[name].wait_for_output(
                LOG + r'\[client_node\]: Sending request\n' + LOG + r'\[client_node\]: Received '
                r'response\n(?:.*\n)*?.*Received response\n(?:.*\n)*?.*Received response$',
                timeout=DEADLOCK_SECONDS + 5)
    time.sleep(max(0.0, DEADLOCK_SECONDS - (time.monotonic() - started)))
    for name, (_lines, works) in CONFIGURATIONS.items():
        output = clients[name].output
        if not works:
            assert output.count('Sending request') == 1, (name, output)
            assert 'Received response' not in output, (name, output)
    # Ctrl-C: each client says the page's line. A stuck one does not exit on it (its
    # executor thread still waits in client.call): a second Ctrl-C ends it.
    for client in clients.values():
        os.killpg(client.popen.pid, signal.SIGINT)
    for client in clients.values():
        client.wait_for_output(LOG + r'\[client_node\]: Keyboard interrupt, shutting down\.$')
        client.stop()
    assert re.search(r'\[service_node\]: Received request, responding\.\.\.$',
                     service_node.output, re.MULTILINE)


def test_synchronous_client_with_a_spinning_thread(module_launch) -> None:
    server = module_launch(argv=['ros2', 'run', 'demo_nodes_py', 'add_two_ints_server'])
    client = module_launch(argv=[sys.executable, str(DATA / 'sync_async' / 'client_sync.py'),
                                 '2', '3'])
    stuck = module_launch(argv=[sys.executable,
                                str(DATA / 'sync_async' / 'client_sync_deadlock.py'), '4', '5'])
    async_client = module_launch(argv=[sys.executable,
                                       str(DATA / 'sync_async' / 'client_async.py'), '6', '7'])
    assert client.wait(timeout=30) == 0
    assert re.search(LOG + r'\[minimal_client_sync\]: Result of add_two_ints: for 2 \+ 3 = 5$',
                     client.output, re.MULTILINE), client.output
    assert async_client.wait(timeout=30) == 0
    assert re.search(LOG + r'\[minimal_client_async\]: Result of add_two_ints: 13$',
                     async_client.output, re.MULTILINE), async_client.output
    trigger = module_launch(argv=['ros2', 'topic', 'pub', '-r', '5', '--times', '5', '/trigger',
                                  'std_msgs/msg/String', "{data: 'go'}"])
    assert trigger.wait(timeout=30) == 0
    server.wait_for_output(r'Incoming request\na: 4 b: 5$', timeout=10)  # asked ...
    time.sleep(1.0)  # ... and the answer, back within milliseconds, is never taken
    assert 'Result of add_two_ints' not in stuck.output
    assert stuck.popen.poll() is None
    for process in (stuck, server):
        process.stop()
