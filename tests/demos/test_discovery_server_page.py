""""Using Fast DDS Discovery Server as discovery protocol" (Jazzy How-to), typed as written.

`fastdds discovery` runs the Fast DDS wheel's fast-discovery-server; nodes given
ROS_DISCOVERY_SERVER become its clients. Shown here as the page shows it: the server's
clients hear each other and not the simple-discovery nodes; nodes started while the server
is down do not meet until it is back; redundant servers, a backup server, partitions; and
the super-client profile that makes `ros2 topic list` and friends see the server's graph.
Ports come from the leased domain (5000 + 4 x domain + k, under Fast DDS's 7400 + 250 x
domain range), on 127.0.0.1 only.
"""

from __future__ import annotations

import os
import re
import signal
import subprocess
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from support import RosProcess, leased_domain, ros_environment

HEARD = re.compile(r'\]: I heard: \[Hello World: (\d+)\]$', re.MULTILINE)
# The page's XML with its port made ours (the prefix is server id 0's, as the page says).
SUPER_CLIENT_XML = """<?xml version="1.0" encoding="UTF-8" ?>
<dds>
    <profiles xmlns="http://www.eprosima.com/XMLSchemas/fastRTPS_Profiles">
        <participant profile_name="super_client_profile" is_default_profile="true">
            <rtps>
                <builtin>
                    <discovery_config>
                        <discoveryProtocol>SUPER_CLIENT</discoveryProtocol>
                        <discoveryServersList>
                            <RemoteServer prefix="44.53.00.5f.45.50.52.4f.53.49.4d.41">
                                <metatrafficUnicastLocatorList>
                                    <locator>
                                        <udpv4>
                                            <address>127.0.0.1</address>
                                            <port>{port}</port>
                                        </udpv4>
                                    </locator>
                                </metatrafficUnicastLocatorList>
                            </RemoteServer>
                        </discoveryServersList>
                    </discovery_config>
                </builtin>
            </rtps>
        </participant>
    </profiles>
</dds>
"""


class Page:
    """The terminals of the page: each command runs in the page's working directory."""

    def __init__(self, domain: int, directory: Path) -> None:
        self.env = ros_environment(domain)
        self.ports = [5000 + 4 * domain + k for k in range(4)]
        self.directory = directory
        self.started: list[RosProcess] = []

    def start(self, *argv: str, server: str | None = None, **extra: str) -> RosProcess:
        env = dict(self.env, **extra)
        if server is not None:
            env['ROS_DISCOVERY_SERVER'] = server
        name = f'{len(self.started):02d}-{argv[0]}-{argv[-1]}'.replace('/', '_')
        process = RosProcess(list(argv), env, self.directory / f'{name}.log',
                             cwd=self.directory)
        self.started.append(process)
        return process

    def close(self) -> None:
        """Ctrl-C every terminal at once (each node takes a moment to exit), then reap."""
        for process in self.started:
            if process.popen.poll() is None:
                try:
                    os.killpg(process.popen.pid, signal.SIGINT)
                except ProcessLookupError:
                    pass
        for process in reversed(self.started):
            process.stop()

    def server(self, *args: str) -> RosProcess:
        process = self.start('fastdds', 'discovery', *args)
        process.wait_for_output(r'^### Server is running ###$', timeout=15)
        return process

    def run(self, *argv: str, **extra: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run(list(argv), env=dict(self.env, **extra), cwd=self.directory,
                              capture_output=True, text=True, timeout=30,
                              stdin=subprocess.DEVNULL)


@pytest.fixture(scope='module')
def page(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Page]:
    with leased_domain() as domain:
        terminals = Page(domain, tmp_path_factory.mktemp('discovery_server'))
        yield terminals
        terminals.close()


def node(name: str) -> tuple[str, ...]:
    return ('--ros-args', '--remap', f'__node:={name}')


def heard(listener: RosProcess) -> list[int]:
    return [int(number) for number in HEARD.findall(listener.output)]


def wait_heard(listener: RosProcess, enough: Callable[[list[int]], bool], what: str,
               timeout: float = 20) -> list[int]:
    import time
    deadline = time.monotonic() + timeout
    while not enough(numbers := heard(listener)):
        assert time.monotonic() < deadline and listener.popen.poll() is None, \
            f'{what} not seen within {timeout} s:\n{listener.output}'
        time.sleep(0.05)
    return numbers


def one_talker(numbers: list[int]) -> bool:
    """A listener of one talker hears consecutive counts; two talkers' counts interleave."""
    return numbers == list(range(numbers[0], numbers[0] + len(numbers)))


def test_talker_and_listener_meet_through_the_server_only(page: Page) -> None:
    server = f'127.0.0.1:{page.ports[0]}'
    first = page.server('--server-id', '0', '--ip-address', '127.0.0.1',
                        '--port', str(page.ports[0]))
    assert f'Server Addresses:   UDPv4:[127.0.0.1]:{page.ports[0]}' in first.output
    listener = page.start('ros2', 'run', 'demo_nodes_cpp', 'listener',
                          *node('listener_discovery_server'), server=server)
    talker = page.start('ros2', 'run', 'demo_nodes_cpp', 'talker',
                        *node('talker_discovery_server'), server=server)
    wait_heard(listener, lambda n: len(n) >= 1, "listener_discovery_server hearing the talker")
    # "Demonstrate Discovery Server execution": simple-discovery nodes do not meet them.
    simple_listener = page.start('ros2', 'run', 'demo_nodes_cpp', 'listener',
                                 *node('simple_listener'))
    page.start('ros2', 'run', 'demo_nodes_cpp', 'talker', *node('simple_talker'))
    simple = wait_heard(simple_listener, lambda n: len(n) >= 3, 'simple_listener hearing')
    talker.wait_for_output(r"Publishing: 'Hello World: \d+'")
    assert one_talker(simple) and simple[0] <= 2, simple_listener.output  # simple_talker's
    assert one_talker(heard(listener)), listener.output  # talker_discovery_server's only

    # The server stopped, new clients do not meet: nothing but the server introduces them.
    assert first.stop() == 0
    for process in (listener, talker):
        assert process.stop() == 0
    late_listener = page.start('ros2', 'run', 'demo_nodes_cpp', 'listener',
                               *node('listener'), server=server)
    late_talker = page.start('ros2', 'run', 'demo_nodes_cpp', 'talker', *node('talker'),
                             server=server)
    late_talker.wait_for_output(r"Publishing: 'Hello World: 3'$", timeout=20)
    assert heard(late_listener) == [], late_listener.output
    # The server back (as the super-client section starts it): they meet through it.
    page.server('-i', '0', '-l', '127.0.0.1', '-p', str(page.ports[0]))
    wait_heard(late_listener, lambda n: len(n) >= 1, 'the late listener hearing, server back')


def test_super_client_daemon_and_no_daemon_tools(page: Page) -> None:
    """Follows the previous test: server 0 with the clients `talker` and `listener` up."""
    (page.directory / 'super_client_configuration_file.xml').write_text(
        SUPER_CLIENT_XML.format(port=page.ports[0]))
    profile = {'FASTRTPS_DEFAULT_PROFILES_FILE': 'super_client_configuration_file.xml'}
    try:
        page.run('ros2', 'daemon', 'stop', **profile)
        assert page.run('ros2', 'daemon', 'start', **profile).stdout \
            == 'The daemon has been started\n'
        topics = page.run('ros2', 'topic', 'list', **profile).stdout.split()
        assert {'/chatter', '/parameter_events', '/rosout'} <= set(topics), topics
        info = page.run('ros2', 'node', 'info', '/talker', **profile).stdout
        assert re.search(r'^  Publishers:\n(    .*\n)*    /chatter: std_msgs/msg/String$', info,
                         re.MULTILINE), info
        topic = page.run('ros2', 'topic', 'info', '/chatter', **profile).stdout
        assert topic == ('Type: std_msgs/msg/String\nPublisher count: 1\n'
                         'Subscription count: 1\n'), topic
        echo = page.start('ros2', 'topic', 'echo', '/chatter', **profile)
        echo.wait_for_output(r"^data: 'Hello World: \d+'\n---$", timeout=20)
        assert echo.stop() in (0, 2)  # Ctrl-C: ros2cli's 2 for an interrupted echo
    finally:
        page.run('ros2', 'daemon', 'stop', **profile)
    info = page.run('ros2', 'node', 'info', '/talker', '--no-daemon', '--spin-time', '2',
                    **profile).stdout
    assert '    /chatter: std_msgs/msg/String' in info, info


def test_redundancy_backup_and_partitions(page: Page) -> None:
    both = f'127.0.0.1:{page.ports[1]};127.0.0.1:{page.ports[2]}'
    backup = page.server('--server-id', '0', '--ip-address', '127.0.0.1',
                         '--port', str(page.ports[1]), '--backup')
    assert 'Participant Type:   BACKUP' in backup.output
    second = page.server('--server-id', '1', '--ip-address', '127.0.0.1',
                         '--port', str(page.ports[2]))
    talker_1 = page.start('ros2', 'run', 'demo_nodes_cpp', 'talker', *node('talker_1'),
                          server=both)
    listener_1 = page.start('ros2', 'run', 'demo_nodes_cpp', 'listener', *node('listener_1'),
                            server=both)
    listener_2 = page.start('ros2', 'run', 'demo_nodes_cpp', 'listener', *node('listener_2'),
                            server=f';127.0.0.1:{page.ports[2]}')
    talker_1.wait_for_output(r"Publishing: 'Hello World: 3'$", timeout=20)
    page.start('ros2', 'run', 'demo_nodes_cpp', 'talker', *node('talker_2'),
               server=f'127.0.0.1:{page.ports[1]}')
    # Listener 1 shares server 0 with talker_2 (counts from 1 again) and hears both talkers.
    wait_heard(listener_1, lambda n: len(n) >= 2 and not one_talker(n),
               'listener_1 hearing talker_1 and talker_2')
    talker_1.wait_for_output(r"Publishing: 'Hello World: \d+'")
    numbers = wait_heard(listener_2, lambda n: len(n) >= 3, 'listener_2 hearing talker_1')
    assert one_talker(numbers), listener_2.output  # talker_1's counts only, not talker_2's
    # The backup server keeps its state in its working directory (SQLite and JSON files).
    files = {path.suffix for path in page.directory.iterdir()}
    assert {'.db', '.json'} <= files, sorted(page.directory.iterdir())
    # Redundancy: server 0 gone, a new listener still meets talker_1 through server 1.
    assert backup.stop() == 0
    listener = page.start('ros2', 'run', 'demo_nodes_cpp', 'listener', *node('listener'),
                          server=both)
    wait_heard(listener, lambda n: len(n) >= 1, 'a listener hearing talker_1 via server 1')
    assert second.popen.poll() is None


def test_the_pages_first_server_listens_on_loopback_only() -> None:
    """`fastdds discovery --server-id 0` (upstream: every interface, port 11811) gets
    127.0.0.1:11811 here; the page's old option names become Fast DDS 2.14's."""
    from fastdds_cli.fastdds import server_arguments
    assert server_arguments(['--server-id', '0']) == [
        '--server-id', '0', '--udp-address', '127.0.0.1', '--udp-port', '11811']
    assert server_arguments(['-i', '1', '--ip-address', '127.0.0.1', '--port=11888', '-b']) == [
        '-i', '1', '--udp-address', '127.0.0.1', '--udp-port=11888', '-b']
    assert server_arguments(['-i', '0', '-x', 'config.xml']) == ['-i', '0', '-x', 'config.xml']
