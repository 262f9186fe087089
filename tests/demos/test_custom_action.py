""""Creating an action" and "Writing an action server and client (Python)" (Jazzy), typed as
the pages say: `ros2 pkg create custom_action_interfaces`, Fibonacci.action, the CMakeLists.txt
and package.xml lines, `colcon build`, `ros2 interface show`; then the page's server and client
run with python3, and `ros2 action list -t`, `ros2 action info`, `ros2 action send_goal
--feedback` as the page shows them.
"""
from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

from ws_testing import colcon_workspace

PAGE_FILES = Path(__file__).parents[1] / 'data' / 'action_tutorial'
ACTION = 'int32 order\n---\nint32[] sequence\n---\nint32[] partial_sequence\n'
CMAKE = '''find_package(rosidl_default_generators REQUIRED)

rosidl_generate_interfaces(${PROJECT_NAME}
  "action/Fibonacci.action"
)

'''
XML = '''  <buildtool_depend>rosidl_default_generators</buildtool_depend>

  <member_of_group>rosidl_interface_packages</member_of_group>

'''


@pytest.fixture(scope='module')
def workspace(tmp_path_factory) -> Path:
    with colcon_workspace(tmp_path_factory) as ws:
        package = ws.create('custom_action_interfaces', '--license', 'Apache-2.0')
        (package / 'action').mkdir()
        (package / 'action' / 'Fibonacci.action').write_text(ACTION)
        cmake = (package / 'CMakeLists.txt').read_text()
        (package / 'CMakeLists.txt').write_text(cmake.replace('ament_package()',
                                                              CMAKE + 'ament_package()'))
        xml = (package / 'package.xml').read_text()
        (package / 'package.xml').write_text(xml.replace('  <export>', XML + '  <export>'))
        ws.build()
    for name in ('fibonacci_action_server.py', 'fibonacci_action_client.py'):
        shutil.copy(PAGE_FILES / name, ws.root)
    return ws.root


def sourced(workspace: Path, command: str) -> list[str]:
    return ['bash', '-c', f'source {workspace}/install/local_setup.bash && {command}']


def test_interface_show(workspace, ros_env) -> None:
    shown = subprocess.run(
        sourced(workspace, 'ros2 interface show custom_action_interfaces/action/Fibonacci'),
        env=ros_env, capture_output=True, text=True, timeout=30)
    assert shown.stdout == ACTION, shown


def test_server_client_and_the_cli(workspace, ros_env, launch) -> None:
    server = launch(argv=sourced(workspace, f'cd {workspace} && exec python3 '
                                 'fibonacci_action_server.py'))

    def ros2(*args: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run(sourced(workspace, 'ros2 ' + ' '.join(args)), env=ros_env,
                              capture_output=True, text=True, timeout=60)

    listed = ros2('action', 'list', '-t')
    for _ in range(50):
        if listed.stdout:
            break
        listed = ros2('action', 'list', '-t')
    assert listed.stdout == '/fibonacci [custom_action_interfaces/action/Fibonacci]\n'
    assert ros2('action', 'info', '/fibonacci').stdout == (
        'Action: /fibonacci\nAction clients: 0\nAction servers: 1\n'
        '    /fibonacci_action_server\n')

    goal = ros2('action', 'send_goal', '--feedback', 'fibonacci',
                'custom_action_interfaces/action/Fibonacci', '"{order: 5}"')
    assert re.fullmatch(
        r'Waiting for an action server to become available\.\.\.\n'
        r'Sending goal:\n     order: 5\n\n'
        r'Goal accepted with ID: [0-9a-f]{32}\n\n'
        r'Feedback:\n    partial_sequence:\n- 0\n- 1\n- 1\n\n'
        r'Feedback:\n    partial_sequence:\n- 0\n- 1\n- 1\n- 2\n\n'
        r'Feedback:\n    partial_sequence:\n- 0\n- 1\n- 1\n- 2\n- 3\n\n'
        r'Feedback:\n    partial_sequence:\n- 0\n- 1\n- 1\n- 2\n- 3\n- 5\n\n'
        r'Result:\n    sequence:\n- 0\n- 1\n- 1\n- 2\n- 3\n- 5\n\n'
        r'Goal finished with status: SUCCEEDED\n', goal.stdout), goal.stdout
    server.wait_for_output(
        r"^\[INFO\] \[[\d.]+\] \[fibonacci_action_server\]: Executing goal\.\.\.\n"
        r"\[INFO\] \[[\d.]+\] \[fibonacci_action_server\]: Feedback: array\('i', \[0, 1, 1\]\)\n"
        r"\[INFO\] \[[\d.]+\] \[fibonacci_action_server\]: Feedback: array\('i', "
        r"\[0, 1, 1, 2\]\)\n")

    client = subprocess.run(sourced(workspace, f'cd {workspace} && python3 '
                                    'fibonacci_action_client.py'),
                            env=ros_env, capture_output=True, text=True, timeout=60)
    assert client.returncode == 0, client
    lines = [re.sub(r'^\[INFO\] \[[\d.]+\] ', '', line) for line in client.stderr.splitlines()]
    # The goal response and the first feedback race in rclpy (both are on the wire when the
    # client spins): either may be logged first.
    assert '[fibonacci_action_client]: Goal accepted :)' in lines[:2], lines
    feedback = [line for line in lines if 'Received feedback' in line]
    assert feedback[0] == "[fibonacci_action_client]: Received feedback: array('i', [0, 1, 1])"
    assert len(feedback) == 9, lines
    assert lines[-1] == ("[fibonacci_action_client]: Result: array('i', "
                         '[0, 1, 1, 2, 3, 5, 8, 13, 21, 34, 55])')
    assert len(lines) == 11, lines  # accepted, 9 feedbacks, the result
    assert server.stop() in (0, -2, 130)  # the page's server has no Ctrl-C handling
