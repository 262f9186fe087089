"""`ros2 run`: ament index lookup, arguments, exit codes and signals of the child."""

import pytest

from ws_testing import ros2


@pytest.fixture
def server(launch):
    process = launch('my_robot_controller', 'add_two_ints_server')
    process.wait_for_output(r'Ready to add two ints')
    return process


def test_run_passes_arguments_and_the_exit_code(ros_env, server):
    result = ros2(ros_env, 'run', 'my_robot_controller', 'add_two_ints_client', '3', '4')
    assert result.returncode == 0, result.stderr
    assert '[add_two_ints_client]: Result of add_two_ints: 3 + 4 = 7' in result.stderr
    server.wait_for_output(r'Incoming request: a=3 b=4')


def test_run_with_ros_args_and_prefix(ros_env, server):
    result = ros2(ros_env, 'run', '--prefix', 'env CLI_PREFIX_SEEN=1', 'my_robot_controller',
                  'add_two_ints_client', '5', '6', '--ros-args', '--log-level', 'info')
    assert result.returncode == 0, result.stderr
    assert 'Result of add_two_ints: 5 + 6 = 11' in result.stderr


def test_run_reports_a_failing_child(ros_env):
    result = ros2(ros_env, 'run', 'my_robot_controller', 'add_two_ints_client', 'x', '1')
    assert result.returncode == 2
    assert result.stdout == '[ros2run]: Process exited with failure 2\n'
    assert "argument 'a' must be an integer" in result.stderr


def test_run_reports_a_child_killed_by_a_signal(ros_env):
    result = ros2(ros_env, 'run', '--prefix', 'sh -c "kill -TERM $$"', 'my_robot_controller',
                  'add_two_ints_client')
    assert result.stdout == '[ros2run]: Terminated\n'
    assert result.returncode == 256 - 15


def test_run_unknown_executable_lists_what_the_package_has(ros_env):
    result = ros2(ros_env, 'run', 'my_robot_controller', 'add_two_ints')
    assert result.returncode == 1
    assert result.stdout == ''
    assert result.stderr.startswith(
        "No executable found\nPackage 'my_robot_controller' has these executables:\n")
    assert '\n  add_two_ints_client\n  add_two_ints_server\n' in result.stderr


def test_run_unknown_package(ros_env):
    result = ros2(ros_env, 'run', 'no_such_package', 'thing')
    assert (result.stdout, result.stderr, result.returncode) == (
        '', "Package 'no_such_package' not found\n", 1)


def test_run_usage_errors(ros_env):
    result = ros2(ros_env, 'run', 'my_robot_controller')
    assert result.returncode == 2
    assert 'the following arguments are required: executable_name' in result.stderr
