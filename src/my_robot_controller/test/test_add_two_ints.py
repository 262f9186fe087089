"""The AddTwoInts server and client as two real processes over DDS."""

import re

import pytest
from example_interfaces.srv import AddTwoInts

from ws_testing import TestNode, wait_until

INT64_MIN, INT64_MAX = -(2**63), 2**63 - 1
RANGE = f'[{INT64_MIN}, {INT64_MAX}]'


@pytest.fixture(scope='module')
def server(module_launch):
    """One server (in module_ros_env) answers every test's requests: it keeps no state."""
    process = module_launch('my_robot_controller', 'add_two_ints_server')
    process.wait_for_output(r'Ready to add two ints')
    return process


def wait_for_new_output(process, pattern: str, since: int) -> None:
    """`pattern` in what the shared process printed after offset `since` (this test's part)."""
    wait_until(lambda: re.search(pattern, process.output[since:], re.MULTILINE), 10,
               f'{pattern!r} in the output of {process.args}')


@pytest.mark.parametrize('a, b, total', [
    (3, 4, 7),
    (-5, -12, -17),
    (-7, 7, 0),
    (INT64_MAX, 0, INT64_MAX),
    (INT64_MIN, 0, INT64_MIN),
    (INT64_MAX, INT64_MIN, -1),
])
def test_client_gets_sum_from_server(module_launch, server, a, b, total):
    since = len(server.output)
    client = module_launch('my_robot_controller', 'add_two_ints_client', str(a), str(b))
    assert client.wait() == 0, client.output
    assert f'[add_two_ints_client]: Result of add_two_ints: {a} + {b} = {total}' in client.output
    wait_for_new_output(server, rf'\[add_two_ints_server\]: Incoming request: a={a} b={b}$',
                        since)
    wait_for_new_output(server, rf'Sending back sum={total}$', since)


def test_client_defaults_to_3_plus_4(module_launch, server):
    client = module_launch('my_robot_controller', 'add_two_ints_client')
    assert client.wait() == 0, client.output
    assert 'Result of add_two_ints: 3 + 4 = 7' in client.output


@pytest.mark.parametrize('args, message', [
    (['x', '1'], f"argument 'a' must be an integer in {RANGE}, got 'x'"),
    (['1', '2.5'], f"argument 'b' must be an integer in {RANGE}, got '2.5'"),
    (['9223372036854775808', '0'], "argument 'a' = 9223372036854775808 is outside int64"),
    (['9223372036854775807', '1'],
     'the sum 9223372036854775807 + 1 = 9223372036854775808 would overflow int64'),
    (['1'], 'expected two integers a and b, got 1 argument(s)'),
])
def test_bad_arguments_get_a_clear_error(launch, args, message):
    client = launch('my_robot_controller', 'add_two_ints_client', *args)
    assert client.wait() == 2
    assert message in client.output
    assert 'Traceback' not in client.output


def test_client_waits_for_late_server(launch):
    # A domain of its own (ros_env): the shared server is not there.
    client = launch('my_robot_controller', 'add_two_ints_client', '20', '22')
    client.wait_for_output(r'\[WARN\] .*service /add_two_ints not available, waiting again\.\.\.')
    launch('my_robot_controller', 'add_two_ints_server')
    assert client.wait() == 0, client.output
    assert 'Result of add_two_ints: 20 + 22 = 42' in client.output


def test_server_survives_overflowing_request(server, module_ros_env):
    probe = TestNode(int(module_ros_env['ROS_DOMAIN_ID']))
    try:
        since = len(server.output)
        response = probe.call(AddTwoInts, '/add_two_ints',
                              AddTwoInts.Request(a=INT64_MAX, b=1))
        assert response.sum == 0
        wait_for_new_output(server, r'\[ERROR\] .*does not fit in int64', since)
        assert probe.call(AddTwoInts, '/add_two_ints', AddTwoInts.Request(a=2, b=2)).sum == 4
    finally:
        probe.close()
