"""`ros2 node`, `ros2 topic` and `ros2 param` against a real node (tests/cli_test_node.py)."""

import re
import signal
import subprocess
import threading
import time

import pytest

from ws_testing import check, cli_test_node_argv, ros2

PARAM_SERVICES = [
    ('/cli_test_node/describe_parameters', 'rcl_interfaces/srv/DescribeParameters'),
    ('/cli_test_node/get_parameter_types', 'rcl_interfaces/srv/GetParameterTypes'),
    ('/cli_test_node/get_parameters', 'rcl_interfaces/srv/GetParameters'),
    ('/cli_test_node/get_type_description',
     'type_description_interfaces/srv/GetTypeDescription'),
    ('/cli_test_node/list_parameters', 'rcl_interfaces/srv/ListParameters'),
    ('/cli_test_node/set_parameters', 'rcl_interfaces/srv/SetParameters'),
    ('/cli_test_node/set_parameters_atomically', 'rcl_interfaces/srv/SetParametersAtomically'),
]
PARAMETERS = ['enabled', 'label', 'ratio', 'speed', 'start_type_description_service',
              'use_sim_time']


@pytest.fixture(scope='module')
def ros_env(module_ros_env):
    """One domain (and one daemon) for the module: every test inspects the one node below."""
    return module_ros_env


@pytest.fixture(scope='module')
def node(module_launch):
    """One cli_test_node for the module: the tests read it, and the one that changes a
    parameter (test_param_set_and_describe) runs after the one that reads their defaults."""
    process = module_launch(argv=cli_test_node_argv())
    process.wait_for_output('^READY$')
    return process


def lines(*items):
    return ''.join(f'{item}\n' for item in items)



# --- ros2 node -----------------------------------------------------------------------------

def test_node_list_and_info(ros_env, node):
    check(ros2(ros_env, 'node', 'list'), '/cli_test_node\n')
    check(ros2(ros_env, 'node', 'list', '-c'), '1\n')
    # The daemon's node is hidden, as ros2cli's `_ros2cli_daemon_<domain>_<id>`.
    everything = ros2(ros_env, 'node', 'list', '-a').stdout.splitlines()
    assert everything[0].startswith(f'/_ros2cli_daemon_{ros_env["ROS_DOMAIN_ID"]}_')
    assert everything[1:] == ['/cli_test_node']
    services = [f'    {name}: {kind}' for name, kind in PARAM_SERVICES]
    check(ros2(ros_env, 'node', 'info', '/cli_test_node'), lines(
        '/cli_test_node',
        '  Subscribers:', '    /heard: std_msgs/msg/String',
        '  Publishers:', '    /parameter_events: rcl_interfaces/msg/ParameterEvent',
        '    /pose: turtlesim/msg/Pose', '    /rosout: rcl_interfaces/msg/Log',
        '  Service Servers:', *services, '    /flag: std_srvs/srv/SetBool',
        '    /pen: turtlesim/srv/SetPen',
        '  Service Clients:', '', '  Action Servers:', '', '  Action Clients:', ''))
    hidden = ros2(ros_env, 'node', 'info', '--include-hidden', '/cli_test_node')
    assert '    /_hidden_flag: std_srvs/srv/SetBool\n' in hidden.stdout
    check(ros2(ros_env, 'node', 'info', '--spin-time', '1', 'cli_test_node'), '',
          "Unable to find node 'cli_test_node'\n", 1)
    # A hidden node (the daemon's) is found only with --include-hidden, as upstream.
    check(ros2(ros_env, 'node', 'info', '--spin-time', '1', everything[0]), '',
          f"Unable to find node '{everything[0]}'\n", 1)
    shown = ros2(ros_env, 'node', 'info', '--include-hidden', everything[0])
    assert (shown.stdout.splitlines()[:2], shown.returncode) == (
        [everything[0], '  Subscribers:'], 0)


# --- ros2 topic ----------------------------------------------------------------------------

def test_topic_list_type_info(ros_env, node):
    topics = [('/heard', 'std_msgs/msg/String'),
              ('/parameter_events', 'rcl_interfaces/msg/ParameterEvent'),
              ('/pose', 'turtlesim/msg/Pose'), ('/rosout', 'rcl_interfaces/msg/Log')]
    check(ros2(ros_env, 'topic', 'list'), lines(*(name for name, _ in topics)))
    check(ros2(ros_env, 'topic', 'list', '-t'), lines(*(f'{n} [{t}]' for n, t in topics)))
    check(ros2(ros_env, 'topic', 'list', '-c'), '4\n')
    # The CLI's own node publishes /parameter_events and /rosout too, as ros2cli's does.
    check(ros2(ros_env, 'topic', 'list', '-v'), lines(
        'Published topics:',
        ' * /parameter_events [rcl_interfaces/msg/ParameterEvent] 2 publishers',
        ' * /pose [turtlesim/msg/Pose] 1 publisher',
        ' * /rosout [rcl_interfaces/msg/Log] 2 publishers', '',
        'Subscribed topics:', ' * /heard [std_msgs/msg/String] 1 subscriber', ''))
    check(ros2(ros_env, 'topic', 'type', '/pose'), 'turtlesim/msg/Pose\n')
    check(ros2(ros_env, 'topic', 'find', 'turtlesim/msg/Pose'), '/pose\n')
    check(ros2(ros_env, 'topic', 'find', '-c', 'rcl_interfaces/msg/Log'), '1\n')
    check(ros2(ros_env, 'topic', 'type', '--spin-time', '1', '/nope'), '', '', 1)
    check(ros2(ros_env, 'topic', 'info', '/pose'),
          'Type: turtlesim/msg/Pose\nPublisher count: 1\nSubscription count: 0\n')
    check(ros2(ros_env, 'topic', 'info', '--spin-time', '1', '/nope'), '',
          "Unknown topic '/nope'\n", 1)


def test_topic_info_verbose(ros_env, node):
    result = ros2(ros_env, 'topic', 'info', '-v', '/pose')
    gid = r'(?:[0-9a-f]{2}\.){15}[0-9a-f]{2}'
    expected = (
        r'Type: turtlesim/msg/Pose\n\nPublisher count: 1\n\n'
        r'Node name: cli_test_node\nNode namespace: /\nTopic type: turtlesim/msg/Pose\n'
        r'Topic type hash: RIHS01_[0-9a-f]{64}\nEndpoint type: PUBLISHER\n'
        rf'GID: {gid}\nQoS profile:\n  Reliability: RELIABLE\n  History \(Depth\): UNKNOWN\n'
        r'  Durability: VOLATILE\n  Lifespan: Infinite\n  Deadline: Infinite\n'
        r'  Liveliness: AUTOMATIC\n  Liveliness lease duration: Infinite\n\n'
        r'Subscription count: 0\n\n')
    assert re.fullmatch(expected, result.stdout), result.stdout


def test_topic_echo(ros_env, node):
    pose = 'x: 1.5\ny: 2.25\ntheta: -0.5\nlinear_velocity: 0.0\nangular_velocity: 0.0\n---\n'
    check(ros2(ros_env, 'topic', 'echo', '--once', '/pose'), pose)
    check(ros2(ros_env, 'topic', 'echo', '--once', '/pose', 'turtlesim/msg/Pose'), pose)
    check(ros2(ros_env, 'topic', 'echo', '--once', '--field', 'theta', '/pose'), '-0.5\n---\n')
    # The warning on stdout, as ros2cli prints it.
    check(ros2(ros_env, 'topic', 'echo', '--spin-time', '1', '--once', '/nope'),
          'WARNING: topic [/nope] does not appear to be published yet\n',
          'Could not determine the type for the passed topic\n', 1)


def interrupt_when(env, argv, enough, timeout=30.0):
    """Run `argv` until its output so far satisfies `enough` (bounded), then Ctrl-C it.

    Waiting for the output rather than a fixed time keeps the test meaningful on a loaded
    machine, where starting and discovering can take seconds. Returns (stdout, stderr).
    """
    process = subprocess.Popen(argv, env=env, text=True, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, start_new_session=True)
    lines: list[str] = []

    def read() -> None:
        for line in process.stdout:
            lines.append(line)
    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    try:
        deadline = time.monotonic() + timeout
        while not enough(''.join(lines)) and time.monotonic() < deadline \
                and process.poll() is None:
            time.sleep(0.05)
        process.send_signal(signal.SIGINT)
        process.wait(timeout=10)
        reader.join(timeout=10)
        return ''.join(lines), process.stderr.read()
    finally:
        process.kill()
        process.wait()


def test_topic_echo_streams_until_interrupted(ros_env, node):
    out, err = interrupt_when(ros_env, ['ros2', 'topic', 'echo', '/pose'],
                              lambda out: out.count('---\n') >= 5)
    assert 'Traceback' not in err
    assert out.count('---\n') >= 5
    assert out.startswith('x: 1.5\n')


def test_topic_pub_once_reaches_the_subscriber(ros_env, node):
    result = ros2(ros_env, 'topic', 'pub', '--once', '/heard', 'std_msgs/msg/String',
                  '{data: hi there}')
    assert result.returncode == 0, result.stderr
    out = re.sub(r'^Waiting for at least 1 matching subscription\(s\)\.\.\.\n', '',
                 result.stdout, flags=re.MULTILINE)
    assert out == ('publisher: beginning loop\n'
                   "publishing #1: std_msgs.msg.String(data='hi there')\n\n")
    node.wait_for_output('^HEARD hi there$')


def test_topic_pub_times_and_bad_values(ros_env, node):
    result = ros2(ros_env, 'topic', 'pub', '-r', '20', '-t', '3', '/heard',
                  'std_msgs/msg/String', 'data: x')
    assert result.stdout.count('publishing #') == 3
    assert 'publishing #3: ' in result.stdout
    bad = ros2(ros_env, 'topic', 'pub', '--once', '/heard', 'std_msgs/msg/String', '{data: 5}')
    check(bad, '', "Failed to populate field: 'data' must be a string, got 5 "
          "(quote it, e.g. '\"123\"')\n", 1)
    check(ros2(ros_env, 'topic', 'pub', '/heard', 'std_msgs/msg/String', '5'), '',
          'The passed value needs to be a dictionary in YAML format\n', 1)
    assert 'HEARD 5' not in node.output


def test_topic_hz(ros_env, node):
    out, err = interrupt_when(ros_env, ['ros2', 'topic', 'hz', '/pose'],
                              lambda out: out.count('average rate: ') >= 2)
    blocks = re.findall(r'average rate: (\d+\.\d{3})\n\tmin: \d+\.\d{3}s max: \d+\.\d{3}s '
                        r'std dev: \d+\.\d{5}s window: (\d+)\n', out)
    assert blocks and len(blocks) * 2 == len(out.splitlines()), out
    assert 12 < float(blocks[-1][0]) < 25  # published at 20 Hz
    assert 'Traceback' not in err


# --- ros2 param ----------------------------------------------------------------------------

def test_param_list_get(ros_env, node):
    check(ros2(ros_env, 'param', 'list', '/cli_test_node'),
          lines(*(f'  {p}' for p in PARAMETERS)))
    check(ros2(ros_env, 'param', 'list'),
          lines('/cli_test_node:', *(f'  {p}' for p in PARAMETERS)))
    # --filter: names the regex matches from their start; a node with none is left out.
    check(ros2(ros_env, 'param', 'list', '/cli_test_node', '--filter', 's.*'),
          lines('  speed', '  start_type_description_service'))
    check(ros2(ros_env, 'param', 'list', '--filter', 'nothing'), '')
    bad = ros2(ros_env, 'param', 'list', '--filter', '(')
    assert (bad.returncode, bad.stderr.splitlines()[-1]) == (2, (
        "ros2 param list: error: argument --filter: '(' is not a regular expression: "
        'missing ), unterminated subpattern at position 0'))
    check(ros2(ros_env, 'param', 'get', '/cli_test_node', 'speed'), 'Integer value is: 69\n')
    check(ros2(ros_env, 'param', 'get', 'cli_test_node', 'ratio'), 'Double value is: 0.5\n')
    check(ros2(ros_env, 'param', 'get', '/cli_test_node', 'label'), 'String value is: hello\n')
    check(ros2(ros_env, 'param', 'get', '/cli_test_node', 'enabled'),
          'Boolean value is: True\n')
    check(ros2(ros_env, 'param', 'get', '/cli_test_node', 'nope'), '', 'Parameter not set\n', 1)
    check(ros2(ros_env, 'param', 'get', '--spin-time', '1', '/nobody', 'speed'), '',
          'Node not found\n', 1)


def test_param_set_and_describe(ros_env, node):
    check(ros2(ros_env, 'param', 'set', '/cli_test_node', 'speed', '150'),
          'Set parameter successful\n')
    check(ros2(ros_env, 'param', 'get', '/cli_test_node', 'speed'), 'Integer value is: 150\n')
    refused = ros2(ros_env, 'param', 'set', '/cli_test_node', 'speed', '300')
    assert refused.stdout == ''
    assert refused.stderr.startswith('Setting parameter failed: ')
    wrong = ros2(ros_env, 'param', 'set', '/cli_test_node', 'speed', 'fast')
    assert wrong.stderr.startswith('Setting parameter failed: ')
    check(ros2(ros_env, 'param', 'get', '/cli_test_node', 'speed'), 'Integer value is: 150\n')
    check(ros2(ros_env, 'param', 'describe', '/cli_test_node', 'speed', 'ratio'), lines(
        'Parameter name: speed', '  Type: integer', '  Description: Speed of the test',
        '  Constraints:', '    Min value: 0', '    Max value: 255', '    Step: 1',
        'Parameter name: ratio', '  Type: double', '  Constraints:'))
