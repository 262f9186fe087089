"""The `ros2` graph daemon: complete, fresh and private answers, and its own lifecycle."""

import json
import os
import signal
import stat
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest
from ros2cli.daemon import client, protocol
from ros2cli.verb_context import CliError

from support import cli_test_node_argv, leased_domain, ros2, ros_environment, stop_daemon


@pytest.fixture
def node(launch):
    process = launch(argv=cli_test_node_argv())
    process.wait_for_output('^READY$')
    return process


def says(env, *args):
    """The stdout of a `ros2` command that must succeed quietly."""
    result = ros2(env, *args)
    assert (result.stderr, result.returncode) == ('', 0), result
    return result.stdout


def daemon_pid(env):
    """The pid of the daemon serving `env`'s settings (None when none answers)."""
    path = protocol.socket_path(env)
    try:
        return client._exchange(path, {'op': 'hello'}, 5.0)['pid']
    except (client.NotRunning, CliError):  # none, or one that just died
        return None


def wait_for(predicate, timeout, what):
    deadline = time.monotonic() + timeout
    while not predicate():
        assert time.monotonic() < deadline, f'timed out after {timeout} s waiting for {what}'
        time.sleep(0.02)


def test_start_status_stop_and_a_private_socket(ros_env):
    assert says(ros_env, 'daemon', 'status') == 'The daemon is not running\n'
    assert says(ros_env, 'daemon', 'stop') == 'The daemon is not running\n'
    assert says(ros_env, 'daemon', 'start') == 'The daemon has been started\n'
    assert says(ros_env, 'daemon', 'start') == 'The daemon is already running\n'
    assert says(ros_env, 'daemon', 'status') == 'The daemon is running\n'
    path = protocol.socket_path(ros_env)
    assert stat.S_ISSOCK(path.stat().st_mode)
    assert stat.S_IMODE(path.stat().st_mode) == 0o600
    assert stat.S_IMODE(path.parent.stat().st_mode) == 0o700
    assert path.parent.stat().st_uid == os.getuid()
    assert says(ros_env, 'daemon', 'stop') == 'The daemon has been stopped\n'
    assert not path.exists()
    assert says(ros_env, 'daemon', 'status') == 'The daemon is not running\n'


def test_a_socket_directory_others_can_enter_is_refused(ros_env, tmp_path):
    shared = tmp_path / 'ros2cli'
    shared.mkdir()
    shared.chmod(0o755)
    result = ros2(dict(ros_env, XDG_RUNTIME_DIR=str(tmp_path)), 'node', 'list')
    assert (result.stdout, result.returncode) == ('', 1)
    assert result.stderr.startswith('Cannot use the ros2 daemon: ') and '0755' in result.stderr
    assert result.stderr.count('\n') == 1 and not list(shared.iterdir())


def test_client_answers_without_rclpy(ros_env, node):
    code = ('import sys\nfrom ros2cli.cli import main\nmain(["node", "list"])\n'
            'print("rclpy" in sys.modules)')
    result = subprocess.run([sys.executable, '-c', code], env=ros_env, capture_output=True,
                            text=True, timeout=60)
    assert result.stdout == '/cli_test_node\nFalse\n', result.stderr


def test_every_answer_complete_also_when_concurrent(ros_env, launch, node):
    turtlesim = launch('turtlesim', 'turtlesim_node', '--headless')
    turtlesim.wait_for_output(r'Spawning turtle \[turtle1\]')
    nodes = '/cli_test_node\n/turtlesim\n'
    assert ros2(ros_env, 'node', 'list').stdout == nodes  # starts the daemon
    services = ros2(ros_env, 'service', 'list').stdout
    assert '/turtle1/set_pen\n' in services and '/flag\n' in services
    answers = [ros2(ros_env, 'node', 'list').stdout for _ in range(10)]
    answers += [ros2(ros_env, 'service', 'list').stdout for _ in range(10)]
    assert answers == [nodes] * 10 + [services] * 10

    # The same graph for other code, as plain data, actions included.
    code = ('import json\nfrom ros2cli.graph import get_graph\ngraph = get_graph()\n'
            'print(json.dumps([graph.actions(), graph.node("/turtlesim").action_servers, '
            'graph.node_names(), graph.topic_counts("/turtle1/pose")]))')
    result = subprocess.run([sys.executable, '-c', code], env=ros_env, capture_output=True,
                            text=True, timeout=60)
    rotate = ['/turtle1/rotate_absolute', ['turtlesim/action/RotateAbsolute']]
    assert json.loads(result.stdout) == [[rotate], [rotate], nodes.split(), [1, 0]], result

    results: list[subprocess.CompletedProcess[str]] = []
    threads = [threading.Thread(target=lambda: results.append(ros2(ros_env, 'service', 'list')))
               for _ in range(20)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join(timeout=60)
    assert [(r.stdout, r.stderr, r.returncode) for r in results] == [(services, '', 0)] * 20


def test_sigkilled_node_is_gone_within_3_s_and_clean_exit_at_once(ros_env, launch, node):
    other = launch('turtlesim', 'turtlesim_node', '--headless')
    other.wait_for_output(r'Spawning turtle \[turtle1\]')
    assert ros2(ros_env, 'node', 'list').stdout == '/cli_test_node\n/turtlesim\n'
    os.killpg(other.popen.pid, signal.SIGKILL)  # not reaped yet: a zombie counts as dead too
    killed = time.monotonic()
    while ros2(ros_env, 'node', 'list').stdout != '/cli_test_node\n':
        assert time.monotonic() - killed < 3.0, 'a SIGKILLed node was still listed after 3 s'
    assert ros2(ros_env, 'service', 'list').stdout.count('/turtle1/') == 0
    assert '/turtle1/pose' not in ros2(ros_env, 'topic', 'list').stdout
    node.stop()
    assert ros2(ros_env, 'node', 'list').stdout == ''


def _queued_connections(path, daemon: int) -> int:
    """How many connections to this path wait in the kernel's queue, not yet accepted: sockets
    carrying the path that no descriptor of the daemon holds (the daemon's own are its
    listening socket and the connections it accepted but has not closed yet)."""
    held = set()
    for fd in Path(f'/proc/{daemon}/fd').iterdir():
        try:
            held.add(os.readlink(fd))
        except OSError:
            continue  # closed meanwhile
    with open('/proc/net/unix') as table:
        return sum(1 for line in table if line.rstrip().endswith(str(path))
                   and f'socket:[{line.split()[6]}]' not in held)


def test_daemon_killed_is_replaced_and_a_crash_mid_call_is_one_line(ros_env, node):
    assert ros2(ros_env, 'node', 'list').stdout == '/cli_test_node\n'
    first = daemon_pid(ros_env)
    os.kill(first, signal.SIGKILL)
    wait_for(lambda: daemon_pid(ros_env) is None, 5, 'the daemon to die')
    assert protocol.socket_path(ros_env).exists()  # a stale socket is left behind
    assert ros2(ros_env, 'node', 'list').stdout == '/cli_test_node\n'
    second = daemon_pid(ros_env)
    assert second not in (None, first)

    # A daemon that dies while a command waits for its answer.
    os.kill(second, signal.SIGSTOP)
    try:
        call = subprocess.Popen(['ros2', 'node', 'list'], env=ros_env, text=True,
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        # The command has connected once the kernel queued its connection on the stopped
        # daemon's socket (a fixed sleep was too short on a loaded machine: the command then
        # found no daemon and started a new one). Counting every socket with the path was not
        # enough: the daemon, stopped right after answering, may still hold that connection.
        wait_for(lambda: _queued_connections(protocol.socket_path(ros_env), second) >= 1, 30,
                 'the command to connect to the stopped daemon')
        os.kill(second, signal.SIGKILL)
    finally:
        os.kill(second, signal.SIGCONT)
    out, err = call.communicate(timeout=30)
    assert (out, call.returncode) == ('', 1)
    assert err.startswith('The ros2 daemon stopped while answering') and err.count('\n') == 1
    assert ros2(ros_env, 'node', 'list').stdout == '/cli_test_node\n'


def test_other_settings_get_their_own_daemon(ros_env, node):
    with leased_domain() as other_domain:
        other = ros_environment(other_domain)
        quiet = dict(ros_env, ROS_AUTOMATIC_DISCOVERY_RANGE='OFF')
        envs = [ros_env, other, quiet]
        try:
            answers: dict[int, str] = {}
            threads = [threading.Thread(target=lambda i=i: answers.__setitem__(
                i, says(envs[i], 'node', 'list'))) for i in range(3)]
            for thread in threads:
                thread.start()
            for thread in threads:
                thread.join(timeout=60)
            assert answers == {0: '/cli_test_node\n', 1: '', 2: ''}
            assert len({protocol.socket_path(env) for env in envs}) == 3
            pids = {daemon_pid(env) for env in envs}
            assert len(pids) == 3 and None not in pids
        finally:
            stop_daemon(other)
            stop_daemon(quiet)
    # --no-daemon discovers with a node of its own (its name is in the hidden list) and
    # neither uses nor starts a daemon.
    assert says(ros_env, 'daemon', 'stop') == 'The daemon has been stopped\n'
    direct = says(ros_env, 'node', 'list', '-a', '--no-daemon').splitlines()
    assert f'/_ros2cli_{direct[0].rsplit("_", 1)[1]}' == direct[0]
    assert says(ros_env, 'daemon', 'status') == 'The daemon is not running\n'


def test_one_shot_verbs_run_in_the_daemon_and_stop_with_their_cli(ros_env, node, launch):
    """With a daemon running, `param get` and `topic echo --once` run in it (the CLI process
    never loads rclpy); with another environment the CLI runs them itself; a CLI killed while
    its verb waits takes the verb's node with it."""
    says(ros_env, 'daemon', 'start')
    assert ros2(ros_env, 'node', 'list').stdout == '/cli_test_node\n'  # the daemon is ready
    code = ('import sys\nfrom ros2cli.cli import main\n'
            'main(["param", "get", "/cli_test_node", "speed"])\n'
            'main(["topic", "echo", "--once", "--field", "x", "/pose"])\n'
            'print("rclpy" in sys.modules)')
    result = subprocess.run([sys.executable, '-c', code], env=ros_env, capture_output=True,
                            text=True, timeout=60)
    assert result.stdout == 'Integer value is: 69\n1.5\n---\nFalse\n', result.stderr
    elsewhere = dict(ros_env, PYTHONPATH=os.pathsep.join([os.devnull,
                                                          ros_env.get('PYTHONPATH', '')]))
    result = subprocess.run([sys.executable, '-c', code], env=elsewhere, capture_output=True,
                            text=True, timeout=60)
    assert result.stdout == 'Integer value is: 69\n1.5\n---\nTrue\n', result.stderr

    waiting = launch(argv=['ros2', 'topic', 'echo', '--once', '/nobody', 'std_msgs/msg/String'])
    verb_node = f'/_ros2cli_{waiting.popen.pid}'
    wait_for(lambda: verb_node in ros2(ros_env, 'node', 'list', '-a').stdout, 20,
             'the verb node in the daemon')
    os.killpg(waiting.popen.pid, signal.SIGKILL)
    wait_for(lambda: verb_node not in ros2(ros_env, 'node', 'list', '-a').stdout, 10,
             'the verb node gone once its CLI was killed')
    assert daemon_pid(ros_env) is not None  # the daemon itself goes on


def test_an_overlay_sourced_after_the_daemon_is_served_by_a_worker(ros_env, node, tmp_path):
    """A shell that sources an overlay after the daemon started: its first one-shot verb runs
    in the CLI while the daemon starts a worker for that environment; the next ones run in
    the worker (the CLI process never loads rclpy); `ros2 daemon stop` ends the worker too."""
    says(ros_env, 'daemon', 'start')
    assert ros2(ros_env, 'node', 'list').stdout == '/cli_test_node\n'  # the daemon is ready
    prefix = tmp_path / 'install'  # an overlay as colcon installs one: a marker, a site dir
    (prefix / 'share' / 'ament_index' / 'resource_index' / 'packages').mkdir(parents=True)
    (prefix / 'share' / 'ament_index' / 'resource_index' / 'packages' / 'overlay').touch()
    site = prefix / 'lib' / f'python{sys.version_info[0]}.{sys.version_info[1]}' / 'site-packages'
    site.mkdir(parents=True)
    sourced = dict(ros_env, AMENT_PREFIX_PATH=f'{prefix}{os.pathsep}{ros_env["AMENT_PREFIX_PATH"]}',
                   PYTHONPATH=os.pathsep.join(filter(None, [str(site),
                                                            ros_env.get('PYTHONPATH')])))
    code = ('import sys\nfrom ros2cli.cli import main\n'
            'main(["param", "get", "/cli_test_node", "speed"])\n'
            'print("rclpy" in sys.modules)')

    def param_get() -> str:
        result = subprocess.run([sys.executable, '-c', code], env=sourced, capture_output=True,
                                text=True, timeout=60)
        assert result.stdout.startswith('Integer value is: 69\n'), result
        return result.stdout
    assert param_get().endswith('True\n')  # in the CLI: the worker is starting
    values = {name: sourced.get(name, '') for name in protocol.ENVIRONMENT}
    worker = protocol.worker_path(protocol.socket_path(ros_env), values)
    wait_for(lambda: worker.exists() and client.is_running(worker), 30, 'the worker')
    wait_for(lambda: param_get().endswith('False\n'), 30, 'the verb to run in the worker')
    assert param_get() == 'Integer value is: 69\nFalse\n'
    worker_pid = client._exchange(worker, {'op': 'hello'}, 5.0)['pid']
    assert worker_pid != daemon_pid(ros_env)
    assert says(ros_env, 'daemon', 'stop') == 'The daemon has been stopped\n'
    assert not os.path.exists(f'/proc/{worker_pid}'), 'the worker outlived its daemon'
    assert param_get().endswith('True\n')  # no daemon: the CLI runs it
