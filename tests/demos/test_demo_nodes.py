"""demo_nodes_py and demo_nodes_cpp as the Jazzy pages run them: `ros2 run demo_nodes_cpp
talker` with `ros2 run demo_nodes_py listener`, the launch files, the AddTwoInts pair, the
QoS, parameter, timer, matched-event and logger-service demos, with upstream's lines."""
from __future__ import annotations

import re

import pytest

from support import ros2

LOG = r'^\[INFO\] \[[\d.]+\] '
PY_EXECUTABLES = {
    'talker', 'listener', 'talker_qos', 'listener_qos', 'listener_serialized',
    'add_two_ints_server', 'add_two_ints_client', 'add_two_ints_client_async',
    'async_param_client', 'set_parameters_callback', 'introspection', 'matched_event_detect',
    'use_logger_service'}
CPP_EXECUTABLES = {
    'talker', 'listener', 'listener_best_effort', 'talker_serialized_message',
    'listener_serialized_message', 'add_two_ints_server', 'add_two_ints_client',
    'add_two_ints_client_async', 'introspection_service', 'introspection_client',
    'parameter_blackboard', 'list_parameters', 'list_parameters_async',
    'set_and_get_parameters', 'set_and_get_parameters_async', 'parameter_events',
    'parameter_events_async', 'parameter_event_handler', 'even_parameters_node',
    'set_parameters_callback', 'one_off_timer', 'reuse_timer', 'matched_event_detect',
    'use_logger_service'}


@pytest.mark.parametrize(('package', 'expected'), [('demo_nodes_py', PY_EXECUTABLES),
                                                   ('demo_nodes_cpp', CPP_EXECUTABLES)])
def test_every_executable_is_listed(module_ros_env, package, expected) -> None:
    listed = ros2(module_ros_env, 'pkg', 'executables', package).stdout.splitlines()
    assert sorted(listed) == sorted(f'{package} {name}' for name in expected)


def test_cpp_talker_to_py_listener(module_launch) -> None:
    talker = module_launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'talker'])
    listener = module_launch(argv=['ros2', 'run', 'demo_nodes_py', 'listener'])
    talker.wait_for_output(LOG + r"\[talker\]: Publishing: 'Hello World: 1'$", timeout=20)
    listener.wait_for_output(LOG + r'\[listener\]: I heard: \[Hello World: \d+\]$', timeout=20)
    assert talker.stop() == 0 and listener.stop() == 0
    assert 'Traceback' not in talker.output + listener.output


def test_serialized_messages(module_launch) -> None:
    talker = module_launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'talker_serialized_message'])
    listener = module_launch(argv=['ros2', 'run', 'demo_nodes_cpp',
                                   'listener_serialized_message'])
    talker.wait_for_output(r'^ROS message:\nHello World:1\nserialized message:\n00 01 00 00 0e 00 '
                           r'00 00 48 65 6c 6c 6f 20 57 6f 72 6c 64 3a 31 00 $', timeout=20)
    listener.wait_for_output(r'^I heard data of length: 2[34]\n00 01 00 00 0e 00 00 00 48 65 6c '
                             r'6c 6f 20 57 6f 72 6c 64 3a \d\d 00 (?:00 )*\nserialized data after '
                             r'deserialization: Hello World:\d$', timeout=20)
    assert talker.stop() == 0 and listener.stop() == 0


def test_py_talker_to_cpp_best_effort_listener(module_launch) -> None:
    talker = module_launch(argv=['ros2', 'run', 'demo_nodes_py', 'talker'])
    listener = module_launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'listener_best_effort'])
    serialized = module_launch(argv=['ros2', 'run', 'demo_nodes_py', 'listener_serialized'])
    talker.wait_for_output(LOG + r'\[talker\]: Publishing: "Hello World: 0"$', timeout=20)
    listener.wait_for_output(LOG + r'\[listener\]: I heard: \[Hello World: \d+\]$', timeout=20)
    # The CDR bytes as Python prints them: header, length, the string and its NUL.
    serialized.wait_for_output(LOG + r'\[serialized_subscriber\]: I heard: "b\'\\x00\\x01\\x00'
                               r'\\x00\\x(?:0f|10)\\x00\\x00\\x00Hello World: \d+(?:\\x00)+\'"$',
                               timeout=20)
    assert talker.stop() == 0 and listener.stop() == 0 and serialized.stop() == 0


def test_talker_listener_launch_files(module_launch) -> None:
    # The three formats at once: each listener hears talkers (its own among them) on /chatter.
    demos = [module_launch(argv=['ros2', 'launch', 'demo_nodes_cpp', launch_file])
             for launch_file in ('talker_listener_launch.py', 'talker_listener_launch.xml',
                                 'talker_listener_launch.yaml')]
    for demo in demos:
        demo.wait_for_output(r"\[talker-1\] \[INFO\] \[[\d.]+\] \[talker\]: Publishing: "
                             r"'Hello World: 1'", timeout=30)
        demo.wait_for_output(r'\[listener-2\] \[INFO\] \[[\d.]+\] \[listener\]: I heard: '
                             r'\[Hello World: \d+\]', timeout=20)
    for demo in demos:
        assert demo.stop() == 0


def test_add_two_ints_launch_ends_with_the_client(module_launch) -> None:
    demo = module_launch(argv=['ros2', 'launch', 'demo_nodes_cpp', 'add_two_ints_launch.py'])
    assert demo.wait(timeout=40) == 0
    assert re.search(r'\[add_two_ints_server\]: Incoming request\n.*a: 2 b: 3', demo.output)
    assert re.search(r'\[add_two_ints_client\]: Result of add_two_ints: 5$', demo.output,
                     re.MULTILINE), demo.output


def test_servers_and_async_clients(module_launch) -> None:
    # Two pairs at once: demo_nodes_py's, and demo_nodes_cpp's with a one-shot server (it ends
    # itself after its first request), remapped to a service of their own.
    once = ['--ros-args', '-r', 'add_two_ints:=add_two_ints_once']
    server = module_launch(argv=['ros2', 'run', 'demo_nodes_py', 'add_two_ints_server'])
    one_shot = module_launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'add_two_ints_server',
                                   *once, '-p', 'one_shot:=true'])
    clients = [module_launch(argv=['ros2', 'run', 'demo_nodes_py', 'add_two_ints_client_async']),
               module_launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'add_two_ints_client_async',
                                   *once])]
    for client in clients:
        assert client.wait(timeout=30) == 0
        assert re.search(LOG + r'\[add_two_ints_client\]: Result of add_two_ints: 5$',
                         client.output, re.MULTILINE), client.output
    for process in (server, one_shot):
        process.wait_for_output(LOG + r'\[add_two_ints_server\]: Incoming request\na: 2 b: 3$')
    assert server.stop() == 0
    assert one_shot.wait(timeout=20) == 0


def test_qos_talker_and_listener_stop_after_n(module_launch) -> None:
    listener = module_launch(argv=['ros2', 'run', 'demo_nodes_py', 'listener_qos', '--reliable',
                                   '-n', '2'])
    listener.wait_for_output(LOG + r'\[listener_qos\]: Reliable listener$')
    talker = module_launch(argv=['ros2', 'run', 'demo_nodes_py', 'talker_qos', '--reliable',
                                 '-n', '4'])
    assert listener.wait(timeout=30) == 0
    assert len(re.findall(r'I heard: \[Hello World: \d+\]', listener.output)) == 2
    assert talker.wait(timeout=30) == 0
    assert re.findall(r'Publishing: "(Hello World: \d+)"', talker.output) == [
        f'Hello World: {n}' for n in range(4)]


def test_qos_bad_option_is_refused(module_ros_env) -> None:
    result = ros2(module_ros_env, 'run', 'demo_nodes_py', 'talker_qos', '--reliability', 'x')
    assert result.returncode == 2
    assert 'error: unrecognized arguments: --reliability x' in result.stderr


def test_parameter_demos_print_upstreams_lines(module_launch) -> None:
    listed = module_launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'list_parameters'])
    got = module_launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'set_and_get_parameters'])
    for process in (listed, got):
        assert process.wait(timeout=40) == 0, process.output
    # Alone: it logs every node's parameter events of the domain.
    events = module_launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'parameter_events'])
    assert events.wait(timeout=40) == 0, events.output
    assert re.search(
        r'\[list_parameters\]: \nParameter names:\n bar\n foo\n foo.first\n foo.second\n'
        r'Parameter prefixes:\n foo\n', listed.output), listed.output
    assert ('\nParameter name: foo\nParameter value (integer): 2\n'
            'Parameter name: baz\nParameter value (double): 1.450000\n'
            'Parameter name: foobarbaz\nParameter value (bool_array): [true, false]\n'
            'Parameter name: toto\nParameter value (byte_array): [0xff, 0x7f]\n') in got.output
    described = re.findall(r'Parameter event:\n new parameters:\n((?:  \w+\n)*) changed '
                           r'parameters:\n((?:  \w+\n)*)', events.output)
    assert len(described) == 10, events.output
    assert [new.split() for new, _changed in described[:4]] == [
        ['foo'], ['bar'], ['baz'], ['foobar']]
    assert [changed.split() for _new, changed in described[4:]] == [
        ['foo'], ['bar'], ['baz'], ['foobar'], ['foo'], ['bar']]


def test_even_parameters_node_and_parameter_event_handler(module_launch, module_ros_env) -> None:
    node = module_launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'even_parameters_node'])
    handler = module_launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'parameter_event_handler'])
    node.wait_for_output(r"Try running 'ros2 param set /even_parameters_node myint 2' to$",
                         timeout=20)
    odd = ros2(module_ros_env, 'param', 'set', '/even_parameters_node', 'myint', '3')
    assert odd.stderr == 'Setting parameter failed: only even integers can be set\n'
    node.wait_for_output(r"Requested value '3' for parameter 'myint' is not an even number: "
                         r'rejecting change\.\.\.$')
    even = ros2(module_ros_env, 'param', 'set', '/even_parameters_node', 'myint', '2')
    assert even.stdout == 'Set parameter successful\n'
    node.wait_for_output(r"parameter 'myint' has changed and is now: 2$")
    assert node.stop() == 0
    # parameter_event_handler, as its own instructions say.
    handler.wait_for_output(r'^\t\$ ros2 param set /a_namespace/a_remote_node a_string_param '
                            r'"string value to set"$', timeout=20)
    assert ros2(module_ros_env, 'param', 'set', 'this_node', 'an_int_param',
                '21').stdout == 'Set parameter successful\n'
    handler.wait_for_output(LOG + r'\[this_node\]: cb1: Received an update to parameter '
                            r'"an_int_param" of type integer: "21"$')
    handler.wait_for_output(LOG + r'\[this_node\]: cb3: Received an update to parameter '
                            r'"an_int_param" of type: integer: "21"$')
    assert ros2(module_ros_env, 'param', 'set', '/a_namespace/a_remote_node', 'a_string_param',
                'hi').stdout == 'Set parameter successful\n'
    handler.wait_for_output(LOG + r'\[this_node\]: cb2: Received an update to parameter '
                            r'"a_string_param" of type: string: "hi"$')
    assert handler.stop() == 0


def test_set_parameters_callbacks(module_launch, module_ros_env) -> None:
    node = module_launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'set_parameters_callback'])
    python_node = module_launch(argv=['ros2', 'run', 'demo_nodes_py', 'set_parameters_callback'])
    node.wait_for_output(r"The 2nd command will set 'param1' to 3\.0 and 'param2' to 4\.0\.$",
                         timeout=20)
    refused = ros2(module_ros_env, 'param', 'set', 'set_param_callback_node', 'param1', '10.0')
    assert refused.stderr == "Setting parameter failed: cannot set 'param1' > 5.0\n"
    assert ros2(module_ros_env, 'param', 'set', 'set_param_callback_node', 'param1',
                '3.0').stdout == 'Set parameter successful\n'
    node.wait_for_output(r"Member variable 'value_1_' set to: 3\.000000\.\n.*"
                         r"Member variable 'value_2_' set to: 4\.000000\.$")
    assert ros2(module_ros_env, 'param', 'get', 'set_param_callback_node',
                'param2').stdout == 'Double value is: 4.0\n'
    assert node.stop() == 0
    # demo_nodes_py's: no limits, and setting param1 sets param2 as well.
    assert ros2(module_ros_env, 'param', 'set', 'set_parameters_callback', 'param1',
                '10.0').stdout == 'Set parameter successful\n'
    assert ros2(module_ros_env, 'param', 'get', 'set_parameters_callback',
                'param2').stdout == 'Double value is: 4.0\n'
    assert python_node.stop() == 0


def test_async_param_client_on_the_blackboard(module_launch) -> None:
    alone = module_launch(argv=['ros2', 'run', 'demo_nodes_py', 'async_param_client'])
    assert alone.wait(timeout=30) == 1
    assert 'parameter_blackboard is not available, start parameter blackboard with ' in \
        alone.output and 'Traceback' not in alone.output
    blackboard = module_launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'parameter_blackboard'])
    blackboard.wait_for_output('ready, and serving', timeout=20)
    client = module_launch(argv=['ros2', 'run', 'demo_nodes_py', 'async_param_client'])
    assert client.wait(timeout=30) == 0, client.output
    lines = [line.split(': ', 1)[1] for line in client.output.splitlines()
             if '[async_param_client]' in line]
    assert lines[:10] == [
        'Setting parameters:', '    int_parameter:', '        successful: True',
        '    bool_parameter:', '        successful: True', '    string_parameter:',
        '        successful: True', 'Listing Parameters:', '    - bool_parameter',
        '    - int_parameter']
    assert '    - string_parameter: Fee Fi Fo Fum' in lines
    assert '        value: I smell the blood of an Englishman' in lines
    assert lines[-3:] == ['    string_parameter:', '        successful: True',
                          '        reason: ']
    assert blackboard.stop() == 0


def test_timers(module_launch) -> None:
    one_off = module_launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'one_off_timer'])
    reuse = module_launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'reuse_timer'])
    for process, name in ((one_off, 'one_off_timer'), (reuse, 'reuse_timer')):
        process.wait_for_output(
            LOG + rf'\[{name}\]: in periodic_timer callback\n.*\[{name}\]:   resetting one off '
            rf'timer\n.*\[{name}\]: in one_off_timer callback$', timeout=20)
    for process in (one_off, reuse):
        assert process.stop() == 0
        assert process.output.count('in one_off_timer callback') == 1


@pytest.mark.parametrize(('package', 'node', 'end'), [
    ('demo_nodes_py', 'matched_event_detection_node', ''),
    ('demo_nodes_cpp', 'matched_event_detect_node', '.')])
def test_matched_event_detect(module_launch, package, node, end) -> None:
    demo = module_launch(argv=['ros2', 'run', package, 'matched_event_detect'])
    assert demo.wait(timeout=60) == 0
    said = [line.split(f'[{node}]: ', 1)[1] for line in demo.output.splitlines()
            if f'[{node}]' in line]
    assert said == [
        'First subscription is connected.',
        'The changed number of connected subscription is 1 and current number of connected '
        f'subscription is 2{end}',
        'The changed number of connected subscription is -1 and current number of connected '
        f'subscription is 1{end}',
        'Last subscription is disconnected.',
        'First publisher is connected.',
        'The changed number of connected publisher is 1 and current number of connected '
        f'publisher is 2{end}',
        'The changed number of connected publisher is -1 and current number of connected '
        f'publisher is 1{end}',
        'Last publisher is disconnected.'], demo.output


def test_use_logger_service(module_launch) -> None:
    demo = module_launch(argv=['ros2', 'run', 'demo_nodes_py', 'use_logger_service'])
    assert demo.wait(timeout=40) == 0
    said = [re.sub(r'^\[(\w+)\] \[[\d.]+\] ', r'\1 ', line) for line in demo.output.splitlines()]
    assert said == [
        'INFO [TestNode]: Output with default logger level:',
        'INFO [LoggerServiceNode]: Output 1 with INFO logger level.',
        'WARN [LoggerServiceNode]: Output 1 with WARN logger level.',
        'ERROR [LoggerServiceNode]: Output 1 with ERROR logger level.',
        'INFO [TestNode]: Current logger level: 0',
        'INFO [TestNode]: Output with debug logger level:',
        'DEBUG [LoggerServiceNode]: Output 2 with DEBUG logger level.',
        'INFO [LoggerServiceNode]: Output 2 with INFO logger level.',
        'WARN [LoggerServiceNode]: Output 2 with WARN logger level.',
        'ERROR [LoggerServiceNode]: Output 2 with ERROR logger level.',
        'INFO [TestNode]: Current logger level: 10',
        'INFO [TestNode]: Output with warn logger level:',
        'WARN [LoggerServiceNode]: Output 3 with WARN logger level.',
        'ERROR [LoggerServiceNode]: Output 3 with ERROR logger level.',
        'INFO [TestNode]: Current logger level: 30',
        'INFO [TestNode]: Output with error logger level:',
        'ERROR [LoggerServiceNode]: Output 4 with ERROR logger level.',
        'INFO [TestNode]: Current logger level: 40'], demo.output
