"""`ros2 service` against a real node: whole outputs as Jazzy prints them, and refused input."""

import time

import pytest

from ws_testing import cli_test_node_argv, ros2

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
SERVICES = [*PARAM_SERVICES, ('/flag', 'std_srvs/srv/SetBool'), ('/pen', 'turtlesim/srv/SetPen')]
UINT8 = '[0, 255]'


@pytest.fixture(scope='module')
def node(module_launch):
    """One cli_test_node for the tests that inspect or call it (in module_ros_env): none
    changes what the others see (its services only log the requests they get)."""
    process = module_launch(argv=cli_test_node_argv())
    process.wait_for_output('^READY$')
    return process


def lines(*items):
    return ''.join(f'{item}\n' for item in items)


def test_list_prints_every_visible_service_sorted(module_ros_env, node):
    first = ros2(module_ros_env, 'service', 'list')  # starts the daemon: complete, if not quick
    start = time.monotonic()
    result = ros2(module_ros_env, 'service', 'list')
    elapsed = time.monotonic() - start
    assert first.stdout == result.stdout
    assert (result.stdout, result.stderr, result.returncode) == (
        lines(*(name for name, _ in SERVICES)), '', 0)
    assert elapsed < 2.5, f'service list took {elapsed:.2f} s'


def test_list_variants(module_ros_env, node):
    typed = ros2(module_ros_env, 'service', 'list', '-t')
    assert typed.stdout == lines(*(f'{name} [{kind}]' for name, kind in SERVICES))
    assert ros2(module_ros_env, 'service', 'list', '-c').stdout == '9\n'
    hidden = [('/_hidden_flag', 'std_srvs/srv/SetBool'), *SERVICES]
    for args in (['service', 'list', '--include-hidden-services'],
                 ['service', '--include-hidden-services', 'list']):
        assert ros2(module_ros_env, *args).stdout == lines(*(name for name, _ in hidden))


def test_type_find_info(module_ros_env, node):
    result = ros2(module_ros_env, 'service', 'type', '/pen')
    assert (result.stdout, result.returncode) == ('turtlesim/srv/SetPen\n', 0)
    unknown = ros2(module_ros_env, 'service', 'type', '--spin-time', '1', '/nope')
    assert (unknown.stdout, unknown.stderr, unknown.returncode) == ('', '', 1)
    hidden = ros2(module_ros_env, 'service', 'type', '--spin-time', '1', '/_hidden_flag')
    assert hidden.returncode == 1
    shown = ros2(module_ros_env, 'service', '--include-hidden-services', 'type', '/_hidden_flag')
    assert shown.stdout == 'std_srvs/srv/SetBool\n'
    found = ros2(module_ros_env, 'service', 'find', 'rcl_interfaces/srv/GetParameters')
    assert found.stdout == '/cli_test_node/get_parameters\n'
    info = ros2(module_ros_env, 'service', 'info', '/flag')
    assert info.stdout == 'Type: std_srvs/srv/SetBool\nClients count: 0\nServices count: 1\n'
    missing = ros2(module_ros_env, 'service', 'info', '--spin-time', '1', '/nope')
    assert (missing.stderr, missing.returncode) == ("Unknown service '/nope'\n", 1)


def test_call_prints_request_and_response(module_ros_env, node):
    result = ros2(module_ros_env, 'service', 'call', '/pen', 'turtlesim/srv/SetPen',
                  '{r: 255, g: 0, b: 0, width: 3, off: 0}')
    # A fresh command node may not have matched /pen within its quiet grace on a loaded machine
    # (CI did so once): it then says so first, as ros2cli always does.
    stdout = result.stdout.removeprefix('waiting for service to become available...\n')
    assert (stdout, result.stderr, result.returncode) == (
        'requester: making request: '
        'turtlesim.srv.SetPen_Request(r=255, g=0, b=0, width=3, off=0)\n\n'
        'response:\nturtlesim.srv.SetPen_Response()\n\n', '', 0)
    node.wait_for_output(r'REQUEST /pen turtlesim\.srv\.SetPen_Request\(r=255, g=0, b=0, '
                         r'width=3, off=0\)')
    flag = ros2(module_ros_env, 'service', 'call', '/flag', 'std_srvs/SetBool', 'data: true')
    # /flag's endpoints are discovered apart from /pen's: when they are not matched yet the
    # command says so first, as ros2cli does.
    assert flag.stdout.removeprefix('waiting for service to become available...\n') == (
        'requester: making request: std_srvs.srv.SetBool_Request(data=True)\n\n'
        "response:\nstd_srvs.srv.SetBool_Response(success=True, message='flag is True')\n\n")


def test_call_yaml_11_keys_are_field_names(module_ros_env, node):
    result = ros2(module_ros_env, 'service', 'call', '/pen', 'turtlesim/srv/SetPen',
                  '{off: 1, r: 7}')
    assert result.returncode == 0, result.stderr
    assert 'SetPen_Request(r=7, g=0, b=0, width=0, off=1)' in result.stdout


def test_call_defaults_and_int_for_float(module_ros_env, node):
    result = ros2(module_ros_env, 'service', 'call', '/pen', 'turtlesim/srv/SetPen')
    assert 'SetPen_Request(r=0, g=0, b=0, width=0, off=0)' in result.stdout
    # ints are fine for float fields (checked on a message only: nothing is sent)
    pub = ros2(module_ros_env, 'topic', 'pub', '--once', '-w', '0', '/nowhere',
               'turtlesim/msg/Pose', '{x: 2, theta: 0.5}')
    assert 'turtlesim.msg.Pose(x=2.0, y=0.0, theta=0.5, linear_velocity=0.0, ' \
           'angular_velocity=0.0)' in pub.stdout
    nan = ros2(module_ros_env, 'topic', 'pub', '--once', '-w', '0', '/nowhere',
               'turtlesim/msg/Pose', '{x: .nan, y: -.inf}')
    assert 'turtlesim.msg.Pose(x=nan, y=-inf, theta=0.0' in nan.stdout, nan.stderr


@pytest.mark.parametrize('type_name, values, message', [
    ('geometry_msgs/msg/Twist', "{linear: {x: 'a'}}", "'linear.x' must be a number, got 'a'"),
    ('geometry_msgs/msg/Twist', '{angular: 3}',
     "'angular' expects a mapping of field names to values, got 3"),
    ('turtlesim/msg/Pose', '{x: 1.0e+39}',
     "'x' must be a float32 in [-3.40282e+38, 3.40282e+38], got 1e+39"),
    ('turtlesim/msg/Color', '{r: 1, yes: 2}',
     "'yes' is not a field of turtlesim/msg/Color (fields: r, g, b)"),
    ('std_msgs/msg/UInt32', '{data: -1}', "'data' must be an integer in [0, 4294967295], got -1"),
])
def test_pub_refuses_bad_values(ros_env, type_name, values, message):
    result = ros2(ros_env, 'topic', 'pub', '--once', '/nowhere', type_name, values)
    assert (result.stdout, result.stderr, result.returncode) == (
        '', f'Failed to populate field: {message}\n', 1)


@pytest.mark.parametrize('values, message', [
    ('{r: 300}', f"'r' must be an integer in {UINT8}, got 300"),
    ('{g: -1}', f"'g' must be an integer in {UINT8}, got -1"),
    ('{width: 2.5}', f"'width' must be an integer in {UINT8}, got 2.5"),
    ("{b: 'red'}", f"'b' must be an integer in {UINT8}, got 'red'"),
    ('{off: true}', f"'off' must be an integer in {UINT8}, got True"),
    ('{colour: 1}', "'colour' is not a field of turtlesim/srv/SetPen_Request "
                    '(fields: r, g, b, width, off)'),
])
def test_call_refuses_bad_values_before_sending(module_ros_env, node, values, message):
    before = len(node.output)  # the shared node logged the other tests' requests
    result = ros2(module_ros_env, 'service', 'call', '/pen', 'turtlesim/srv/SetPen', values)
    assert (result.stdout, result.stderr, result.returncode) == (
        '', f'Failed to populate field: {message}\n', 1)
    assert 'REQUEST' not in node.output[before:]


def test_call_refuses_int64_overflow_and_non_mapping(ros_env):
    big = ros2(ros_env, 'service', 'call', '/add_two_ints', 'example_interfaces/srv/AddTwoInts',
               '{a: 9223372036854775808}')
    assert big.stderr == ("Failed to populate field: 'a' must be an integer in "
                          '[-9223372036854775808, 9223372036854775807], '
                          'got 9223372036854775808\n')
    listed = ros2(ros_env, 'service', 'call', '/x', 'std_srvs/srv/Empty', '[1, 2]')
    assert (listed.stderr, listed.returncode) == (
        'The passed value needs to be a dictionary in YAML format\n', 1)
    flag = ros2(ros_env, 'service', 'call', '/flag', 'std_srvs/srv/SetBool', '{data: 1}')
    assert flag.stderr == ("Failed to populate field: 'data' must be a boolean (true or false), "
                           'got 1\n')


def test_call_bad_type(ros_env):
    for bad in ('nope/srv/Nope', 'turtlesim/srv/Nope', 'justaname'):
        result = ros2(ros_env, 'service', 'call', '/x', bad)
        assert (result.stderr, result.returncode) == ('The passed service type is invalid\n', 1)


def test_call_gives_up_when_the_service_never_appears(ros_env):
    start = time.monotonic()
    result = ros2(ros_env, 'service', 'call', '--timeout', '2.5', '/absent',
                  'std_srvs/srv/Empty')
    elapsed = time.monotonic() - start
    assert result.stdout == 'waiting for service to become available...\n'
    assert result.stderr == ("Service '/absent' did not become available within 2.5 s "
                             '(is its node running? see `ros2 service list`)\n')
    assert result.returncode == 1
    assert 2.5 < elapsed < 5


def test_call_waits_for_a_late_service(ros_env, launch):
    import subprocess
    # The node comes after the 3 s of quiet waiting; the timeout leaves it time to start.
    call = subprocess.Popen(['ros2', 'service', 'call', '--timeout', '20', '/flag',
                             'std_srvs/srv/SetBool', '{data: false}'], env=ros_env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        time.sleep(4.5)
        launch(argv=cli_test_node_argv())
        out, err = call.communicate(timeout=30)
    finally:
        call.kill()
    assert call.returncode == 0, err
    assert out.startswith('waiting for service to become available...\n'
                          'requester: making request: std_srvs.srv.SetBool_Request(data=False)')
