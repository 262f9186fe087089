"""Shared test helpers: ROS domains, node processes, and an in-test rclpy node.

Imported as `from ws_testing import RosProcess, ...` (tests/support.py re-exports it for the
tests that still say `from support import ...`).

Every test talks real DDS on loopback (ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST) in a
ROS_DOMAIN_ID leased for that test only, so concurrent test runs never hear each other.
"""

from __future__ import annotations

import fcntl
import importlib
import itertools
import os
import pty
import re
import signal
import subprocess
import termios
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import rclpy
from ament_index_python.packages import get_package_prefix
from node_runtime.discovery import announce_often, is_ours
from rclpy.context import Context
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node


def _workspace_root() -> Path:
    """The repository the tests run in: the folder with tools/test_only_packages.txt above this
    file (a symlink install) or above the working directory (`colcon test` runs in the
    package's folder); the working directory if neither has it."""
    for start in (Path(__file__).resolve(), Path.cwd()):
        for folder in start.parents:
            if (folder / 'tools' / 'test_only_packages.txt').is_file():
                return folder
    return Path.cwd()


REPO = _workspace_root()
LOCK_DIR = Path('/tmp/turtle-ws-domains')
# Fast DDS maps a domain to UDP ports 7400 + 250 * id: ids up to 232 are valid on Linux.
DOMAIN_IDS = range(1, 230)


_LEASES = itertools.count()

# Every domain this test session leased: at its end, their `ros2` daemons are stopped (conftest).
LEASED_DOMAINS: set[int] = set()


@contextmanager
def leased_domain() -> Iterator[int]:
    """Hold an exclusive lock on a free ROS_DOMAIN_ID for the duration of the block."""
    LOCK_DIR.mkdir(exist_ok=True)
    # Each lease of a process starts further on, so a test does not get the domain the test
    # before it just gave back: a participant of that test's probe whose destruction rclpy
    # deferred would still be in it (seen: /test_probe in the next module's `ros2 node list`).
    start = (os.getpid() * 7 + next(_LEASES) * 11) % len(DOMAIN_IDS)
    for offset in range(len(DOMAIN_IDS)):
        domain = DOMAIN_IDS[(start + offset) % len(DOMAIN_IDS)]
        handle = open(LOCK_DIR / f'{domain}.lock', 'w')
        try:
            fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            handle.close()
            continue
        LEASED_DOMAINS.add(domain)
        try:
            yield domain
        finally:
            try:
                # A `ros2` graph verb run in this domain started a daemon: it goes with the
                # lease (the next holder of the domain must not find it, nor the leak check).
                stop_daemon(ros_environment(domain))
            finally:
                handle.close()
        return
    raise RuntimeError('no free ROS_DOMAIN_ID left to lease')


def ros_environment(domain: int) -> dict[str, str]:
    env = dict(os.environ)
    if is_ours(env.get('FASTRTPS_DEFAULT_PROFILES_FILE')):
        # Set for the probe (TestNode): processes under test choose their own, as for a user.
        del env['FASTRTPS_DEFAULT_PROFILES_FILE']
    env['ROS_DOMAIN_ID'] = str(domain)
    env['ROS_AUTOMATIC_DISCOVERY_RANGE'] = 'LOCALHOST'
    env['PYTHONUNBUFFERED'] = '1'
    env['RCUTILS_COLORIZED_OUTPUT'] = '0'
    env.setdefault('QT_QPA_PLATFORM', 'offscreen')
    return env


def interface_type(name: str) -> Any:
    """The generated class for 'pkg/kind/Name' (e.g. 'turtlesim/srv/SetPen')."""
    package, kind, type_name = name.split('/')
    return getattr(importlib.import_module(f'{package}.{kind}'), type_name)


def executable(package: str, name: str) -> str:
    """Path of an installed executable, as `ros2 run` finds it."""
    path = Path(get_package_prefix(package)) / 'lib' / package / name
    if not os.access(path, os.X_OK):
        raise FileNotFoundError(f'{package} has no executable {name} at {path}')
    return str(path)


class RosProcess:
    """A node (or any command) run as a child process with its output kept in a file."""

    def __init__(self, args: list[str], env: dict[str, str], log_path: Path,
                 cwd: Path | None = None) -> None:
        self.args = args
        self.log_path = log_path
        self._log = open(log_path, 'wb')
        self.popen = subprocess.Popen(
            args, env=env, cwd=cwd, stdin=subprocess.DEVNULL, stdout=self._log,
            stderr=subprocess.STDOUT, start_new_session=True)

    @property
    def output(self) -> str:
        return self.log_path.read_text(errors='replace')

    def wait_for_output(self, pattern: str, timeout: float = 10.0) -> re.Match[str]:
        """Wait until `pattern` (a regex) appears in the output; fail with the output."""
        deadline = time.monotonic() + timeout
        while True:
            match = re.search(pattern, self.output, re.MULTILINE)
            if match:
                return match
            if time.monotonic() > deadline or self.popen.poll() is not None:
                raise AssertionError(
                    f'{pattern!r} not seen in the output of {self.args} within {timeout} s '
                    f'(exit code {self.popen.poll()}):\n{self.output}')
            time.sleep(0.05)

    def wait(self, timeout: float = 20.0) -> int:
        return self.popen.wait(timeout=timeout)

    def stop(self, timeout: float = 5.0) -> int:
        """Ctrl-C the process group like a terminal would; kill it if it does not exit."""
        if self.popen.poll() is None:
            try:
                os.killpg(self.popen.pid, signal.SIGINT)
                self.popen.wait(timeout=timeout)
            except subprocess.TimeoutExpired:
                os.killpg(self.popen.pid, signal.SIGKILL)
                self.popen.wait()
            except ProcessLookupError:
                pass
        self._log.close()
        return self.popen.returncode


class TestNode:
    """An rclpy node in a private context on the test's domain, spun on demand."""

    __test__ = False  # a helper, not a test class for pytest to collect

    def __init__(self, domain: int, name: str = 'test_probe') -> None:
        # Announced every 0.5 s, as our nodes are: a restarted turtlesim then meets the probe
        # about as soon as it meets turtle_controller, not at the probe's next announcement
        # 3 s later (the probe heard a new turtle 3 s after the controller did).
        announce_often(fresh_port=False)  # a test may hold several probes at once
        self.context = Context()
        rclpy.init(context=self.context, domain_id=domain)
        self.node = Node(name, context=self.context)
        self.executor = SingleThreadedExecutor(context=self.context)
        self.executor.add_node(self.node)
        self._clients: dict[tuple[Any, str], Any] = {}

    def spin_for(self, seconds: float) -> None:
        deadline = time.monotonic() + seconds
        while time.monotonic() < deadline:
            self.executor.spin_once(timeout_sec=min(0.05, max(0.0, deadline - time.monotonic())))

    def spin_until(self, predicate: Callable[[], bool], timeout: float, what: str) -> None:
        deadline = time.monotonic() + timeout
        while not predicate():
            if time.monotonic() > deadline:
                raise AssertionError(f'timed out after {timeout} s waiting for {what}')
            self.executor.spin_once(timeout_sec=0.05)

    def client(self, srv_type: Any, name: str) -> Any:
        """The probe's one client of service `name`, made on first use and kept.

        Kept, because a server answers a new client only once its own side has matched the
        client's response reader, which can trail the client's view (wait_for_service) by more
        than the 100 ms Fast DDS's server waits for it under load: the response is dropped
        (seen: ~/burst of the bag player unanswered after 10 s, one call in a run of eight).
        A test that must not meet that race at all makes its clients before the server starts.
        """
        key = (srv_type, name)
        if key not in self._clients:
            self._clients[key] = self.node.create_client(srv_type, name)
        return self._clients[key]

    def call(self, srv_type: Any, name: str, request: Any, timeout: float = 10.0) -> Any:
        """Call a service (waiting for it first) and return the response."""
        client = self.client(srv_type, name)
        if not client.wait_for_service(timeout_sec=timeout):
            raise AssertionError(f'service {name} did not appear within {timeout} s')
        future = client.call_async(request)
        self.executor.spin_until_future_complete(future, timeout_sec=timeout)
        if not future.done():
            client.remove_pending_request(future)
            raise AssertionError(f'service {name} did not answer within {timeout} s')
        return future.result()

    def collect(self, msg_type: Any, topic: str, qos: Any = 10) -> list[Any]:
        """Subscribe and return the list that received messages are appended to."""
        received: list[Any] = []
        self.node.create_subscription(msg_type, topic, received.append, qos)
        return received

    def close(self) -> None:
        self.executor.shutdown()
        self.node.destroy_node()
        rclpy.shutdown(context=self.context)


class Background:
    """Spin a TestNode on a thread, for tests that must block elsewhere meanwhile."""

    def __init__(self, probe: TestNode) -> None:
        self._probe = probe
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, daemon=True)

    def _run(self) -> None:
        while not self._stop.is_set():
            self._probe.executor.spin_once(timeout_sec=0.05)

    def __enter__(self) -> Background:
        self._thread.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self._stop.set()
        self._thread.join(timeout=5)


# --- processes a test leaves behind (ws_testing/leak_check.py) ------------------------------------

# Every process started while a test (module, session) runs inherits this variable from the test
# process's environment (ros_environment() copies it too), and so do its descendants, reparented
# or not: what still carries a scope's value when the scope ends is a leak.
OWNER_VARIABLE = 'TURTLE_WS_TEST_OWNER'
# A stopped `ros2 launch` escalates SIGINT -> SIGTERM (5 s) -> SIGKILL (5 s more): a process gets
# that long to exit after its scope's fixtures stopped it, before it counts as left behind.
LEFTOVER_GRACE = 11.0


def owner_token(scope: str) -> str:
    """The variable's value for a scope (a test id, a module): this session's pid first."""
    return f'{os.getpid()} {scope}'


def processes_owned(matches: Callable[[str], bool], variable: str = OWNER_VARIABLE
                    ) -> dict[int, str]:
    """pid -> command line of the running processes whose `variable` value `matches`."""
    prefix = f'{variable}='.encode()
    found: dict[int, str] = {}
    for entry in os.scandir('/proc'):
        if not entry.name.isdigit() or int(entry.name) == os.getpid():
            continue
        try:
            with open(f'/proc/{entry.name}/environ', 'rb') as environ:
                variables = environ.read().split(b'\0')
            with open(f'/proc/{entry.name}/cmdline', 'rb') as cmdline:
                command = cmdline.read().replace(b'\0', b' ').decode(errors='replace').strip()
        except OSError:  # gone meanwhile, or not ours to read
            continue
        owner = next((v[len(prefix):].decode(errors='replace') for v in variables
                      if v.startswith(prefix)), None)
        if owner is not None and command and matches(owner):  # a zombie has no command line
            found[int(entry.name)] = command
    return found


def stop_leftovers(matches: Callable[[str], bool], grace: float = LEFTOVER_GRACE) -> list[str]:
    """Wait up to `grace` s for the matching processes to exit; SIGKILL those still running and
    return them as 'pid N: command line' (empty when nothing was left)."""
    deadline = time.monotonic() + grace
    left = processes_owned(matches)
    while left and time.monotonic() < deadline:
        time.sleep(0.05)
        left = processes_owned(matches)
    for pid in left:
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    return [f'pid {pid}: {command}' for pid, command in sorted(left.items())]


# --- turtle_controller tests ------------------------------------------------------------------

def turtle_qos() -> Any:
    """turtlesim's QoS for turtle topics (keep-last 7, reliable, volatile)."""
    from rclpy.qos import DurabilityPolicy, HistoryPolicy, QoSProfile, ReliabilityPolicy
    return QoSProfile(history=HistoryPolicy.KEEP_LAST, depth=7,
                      reliability=ReliabilityPolicy.RELIABLE,
                      durability=DurabilityPolicy.VOLATILE)


def collect_stamped(probe: TestNode, msg_type: Any, topic: str,
                    qos: Any = None) -> list[tuple[float, Any]]:
    """Like TestNode.collect, but each message comes with its wall-clock arrival time."""
    received: list[tuple[float, Any]] = []
    probe.node.create_subscription(
        msg_type, topic, lambda msg: received.append((time.time(), msg)),
        turtle_qos() if qos is None else qos)
    return received


# --- ros2 CLI tests (tests/test_cli_*.py) -------------------------------------------------------

def stop_daemon(env: dict[str, str]) -> None:
    """Stop the `ros2` graph daemon of `env`'s settings, if a command of the test started one."""
    try:
        from ros2cli.daemon import client, protocol
    except ImportError:  # apt Jazzy's ros2cli: its daemon listens on 11511 + the domain id
        import socket
        port = 11511 + int(env.get('ROS_DOMAIN_ID', '0'))
        with socket.socket() as probe:
            if probe.connect_ex(('127.0.0.1', port)) != 0:
                return
        subprocess.run(['ros2', 'daemon', 'stop'], env=env, capture_output=True, timeout=30,
                       stdin=subprocess.DEVNULL, check=False)
        return
    path = protocol.socket_path(env)
    if path.exists() or path.with_suffix('.lock').exists():
        client.stop(path)


def ros2(env: dict[str, str], *args: str, timeout: float = 30.0,
         stdin: str | None = None) -> subprocess.CompletedProcess[str]:
    """Run the workspace's `ros2` command to completion and capture its output."""
    return subprocess.run(['ros2', *args], env=env, capture_output=True, text=True,
                          timeout=timeout, input=stdin,
                          stdin=None if stdin is not None else subprocess.DEVNULL)


def ros2_side_by_side(env: dict[str, str], *commands: list[str], timeout: float = 30.0
                      ) -> list[subprocess.CompletedProcess[str]]:
    """Run independent `ros2` commands at once (each waits out a limit of its own), to the end
    of all; their results in order, as ros2() gives them."""
    started = [subprocess.Popen(['ros2', *args], env=env, text=True, stdin=subprocess.DEVNULL,
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE)
               for args in commands]
    try:
        outputs = [process.communicate(timeout=timeout) for process in started]
    finally:
        for process in started:
            if process.poll() is None:
                process.kill()
                process.communicate()
    return [subprocess.CompletedProcess(process.args, process.returncode, out, err)
            for process, (out, err) in zip(started, outputs, strict=True)]


def cli_test_node_argv() -> list[str]:
    """Command line of tests/cli_test_node.py (services, a topic and parameters to inspect)."""
    import sys
    return [sys.executable, str(REPO / 'tests' / 'cli_test_node.py')]


def check(result: subprocess.CompletedProcess[str], stdout: str, stderr: str = '',
          code: int = 0) -> None:
    """A command's whole output and exit code in one comparison (pytest shows what differs)."""
    assert (result.stdout, result.stderr, result.returncode) == (stdout, stderr, code), result


def wait_until(predicate: Callable[[], bool], timeout: float, what: str) -> None:
    """Poll `predicate` (while a Background spinner receives messages); fail after timeout."""
    deadline = time.monotonic() + timeout
    while not predicate():
        if time.monotonic() > deadline:
            raise AssertionError(f'timed out after {timeout} s waiting for {what}')
        time.sleep(0.02)


def run_checked(args: list[str], cwd: Path, env: dict[str, str], timeout: float = 240.0
                ) -> subprocess.CompletedProcess[str]:
    """Run a command to completion (a tutorial step: `colcon build`, `ros2 pkg create`...);
    fail the test with its output if it fails."""
    result = subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True,
                            timeout=timeout, stdin=subprocess.DEVNULL)
    assert result.returncode == 0, f'{args} failed:\n{result.stdout}\n{result.stderr}'
    return result


class Terminal:
    """A command on a pseudo-terminal (a keyboard teleop reads keys from one), its output
    read on a thread."""

    def __init__(self, argv: list[str], env: dict[str, str]) -> None:
        self.master, self.slave = pty.openpty()
        self.before = termios.tcgetattr(self.slave)
        self.process = subprocess.Popen(
            argv, stdin=self.slave, stdout=self.slave, stderr=self.slave, env=env,
            start_new_session=True)
        self.output = b''
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self) -> None:
        while True:
            try:
                data = os.read(self.master, 1024)
            except OSError:
                return
            if not data:
                return
            self.output += data

    @property
    def text(self) -> str:
        return self.output.replace(b'\r\n', b'\n').decode(errors='replace')

    def wait_for_output(self, text: str, timeout: float = 10.0) -> None:
        deadline = time.monotonic() + timeout
        while text not in self.text:
            assert time.monotonic() < deadline, self.text
            time.sleep(0.05)

    def press(self, keys: bytes) -> None:
        os.write(self.master, keys)

    def close(self) -> None:
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()
        os.close(self.slave)
        os.close(self.master)
