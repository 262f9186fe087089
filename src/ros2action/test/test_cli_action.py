"""`ros2 action` on turtlesim's /turtle1/rotate_absolute: Jazzy's outputs, Ctrl-C, bad input."""

import os
import re
import signal

import pytest

from ws_testing import RosProcess, check, ros2

ACTION = '/turtle1/rotate_absolute'
TYPE = 'turtlesim/action/RotateAbsolute'
GOAL_ID = r'[0-9a-f]{32}'
NUMBER = r'-?\d+\.\d+(?:e-?\d+)?'


@pytest.fixture(scope='module')
def turtlesim(module_turtlesim):
    return module_turtlesim



def test_list_type_info(module_ros_env, turtlesim):
    env = module_ros_env
    check(ros2(env, 'action', 'list'), f'{ACTION}\n')
    check(ros2(env, 'action', 'list', '-t'), f'{ACTION} [{TYPE}]\n')
    check(ros2(env, 'action', 'type', ACTION), f'{TYPE}\n')
    check(ros2(env, 'action', 'info', ACTION),
          f'Action: {ACTION}\nAction clients: 0\nAction servers: 1\n    /turtlesim\n')
    check(ros2(env, 'action', 'info', '-t', ACTION),
          f'Action: {ACTION}\nAction clients: 0\nAction servers: 1\n    /turtlesim [{TYPE}]\n')
    check(ros2(env, 'action', 'type', '--spin-time', '1', '/nope'), '', '', 1)
    check(ros2(env, 'action', 'info', 'bad name'), '',
          "Invalid action name 'bad name': topic name must not contain characters other than "
          "alphanumerics, '_', or '/'\n", 1)


def test_send_goal_prints_jazzys_transcript(module_ros_env, turtlesim):
    result = ros2(module_ros_env, 'action', 'send_goal', ACTION, TYPE, '{theta: 1.57}')
    assert result.returncode == 0, result.stderr
    assert re.fullmatch(
        'Waiting for an action server to become available...\n'
        'Sending goal:\n     theta: 1.57\n\n'
        f'Goal accepted with ID: {GOAL_ID}\n\n'
        f'Result:\n    delta: {NUMBER}\n\n'
        'Goal finished with status: SUCCEEDED\n', result.stdout), result.stdout
    turtlesim.wait_for_output('Rotation goal completed successfully')


def test_send_goal_with_feedback(module_ros_env, turtlesim):
    result = ros2(module_ros_env, 'action', 'send_goal', ACTION, TYPE, '{theta: -1.0}',
                  '--feedback')
    assert result.returncode == 0, result.stderr
    match = re.fullmatch(
        'Waiting for an action server to become available...\n'
        'Sending goal:\n     theta: -1.0\n\n'
        f'Goal accepted with ID: {GOAL_ID}\n\n'
        f'((?:Feedback:\n    remaining: {NUMBER}\n\n)+)'
        f'Result:\n    delta: {NUMBER}\n\n'
        'Goal finished with status: SUCCEEDED\n', result.stdout)
    assert match, result.stdout
    remaining = [abs(float(v)) for v in re.findall(rf'remaining: ({NUMBER})', match.group(1))]
    assert len(remaining) >= 3 and remaining[-1] < remaining[0], remaining


def test_ctrl_c_cancels_the_goal(module_ros_env, turtlesim, tmp_path):
    # From any heading the earlier tests leave (0, 1.57 or -1.0) this turn takes turtlesim
    # 2 s or more: Ctrl-C lands while the goal runs.
    command = RosProcess(['ros2', 'action', 'send_goal', ACTION, TYPE, '{theta: 2.0}'],
                         module_ros_env,
                         tmp_path / 'send_goal.log')
    try:
        command.wait_for_output(f'Goal accepted with ID: {GOAL_ID}', timeout=15)
        os.killpg(command.popen.pid, signal.SIGINT)
        assert command.wait(timeout=15) == signal.SIGINT
    finally:
        command.stop()
    assert re.search(f'Goal accepted with ID: {GOAL_ID}\n\nCanceling goal...\nGoal canceled.\n$',
                     command.output), command.output
    turtlesim.wait_for_output('Rotation goal canceled')


@pytest.mark.parametrize(('args', 'error'), [
    ([TYPE.replace('Rotate', 'Spin'), '{theta: 1.0}'], 'The passed action type is invalid\n'),
    (['turtlesim/srv/SetPen', '{}'], 'The passed action type is invalid\n'),
    ([TYPE, '{theta: abc}'], "Failed to populate field: 'theta' must be a number, got 'abc'\n"),
    ([TYPE, '{angle: 1.0}'], "Failed to populate field: 'angle' is not a field of "
                             'turtlesim/action/RotateAbsolute_Goal (fields: theta)\n'),
    ([TYPE, '[1, 2]'], 'The passed value needs to be a dictionary in YAML format\n'),
    ([TYPE, '{theta: [}'], "The passed value is not valid YAML: expected the node content, "
                           "but found '}' (line 1, column 10)\n"),
])
def test_send_goal_refuses_bad_input(module_ros_env, args, error):
    # Checked before any node exists: nothing is sent.
    check(ros2(module_ros_env, 'action', 'send_goal', ACTION, *args), '', error, 1)


def test_send_goal_to_unknown_action_gives_up(module_ros_env, turtlesim):
    result = ros2(module_ros_env, 'action', 'send_goal', '--timeout', '1', '/turtle9/rotate',
                  TYPE, '{theta: 1.0}')
    check(result, 'Waiting for an action server to become available...\n',
          "Action server '/turtle9/rotate' did not become available within 1 s (is its node "
          'running? see `ros2 action list`)\n', 1)
