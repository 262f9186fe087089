"""nav2_lifecycle_manager drives map_server and map_saver_server through their lifecycles;
bad command lines are refused in one line."""

from __future__ import annotations

import re

from lifecycle_msgs.msg import State
from lifecycle_msgs.srv import GetState
from nav2_msgs.srv import ManageLifecycleNodes
from rcl_interfaces.srv import GetParameters
from std_srvs.srv import Trigger

from ws_testing import executable

MANAGED = ('map_server', 'map_saver')


def state_of(probe, node: str) -> int:
    return probe.call(GetState, f'/{node}/get_state', GetState.Request()).current_state.id


def manage(probe, command: int) -> bool:
    request = ManageLifecycleNodes.Request(command=command)
    return probe.call(ManageLifecycleNodes, '/lifecycle_manager/manage_nodes', request,
                      timeout=30).success


def is_active(probe) -> bool:
    return probe.call(Trigger, '/lifecycle_manager/is_active', Trigger.Request()).success


def test_startup_then_shutdown_leaves_no_node_active(launch, probe):
    map_server = launch('nav2_map_server', 'map_server', '--ros-args',
                        '-p', "yaml_filename:=''")
    saver = launch('nav2_map_server', 'map_saver_server')
    manager = launch('nav2_lifecycle_manager', 'lifecycle_manager', '--ros-args',
                     '-p', f'node_names:={list(MANAGED)}')
    manager.wait_for_output('Creating and initializing lifecycle service clients')
    assert not is_active(probe)
    assert manage(probe, ManageLifecycleNodes.Request.STARTUP)
    assert is_active(probe)
    assert [state_of(probe, node) for node in MANAGED] == [State.PRIMARY_STATE_ACTIVE] * 2
    # upstream's lines, in order: configure all in the given order, then activate all
    steps = re.findall(r'\[lifecycle_manager\]: \x1b\[34m\x1b\[1m(.*?)\x1b', manager.output)
    assert steps[steps.index('Starting managed nodes bringup...'):] == [
        'Starting managed nodes bringup...', 'Configuring map_server', 'Configuring map_saver',
        'Activating map_server', 'Activating map_saver', 'Managed nodes are active']
    map_server.wait_for_output(r'\[map_server\]: Configuring\n(.|\n)*\[map_server\]: Activating')
    map_server.wait_for_output("yaml-filename parameter is empty, set map through "
                               "'load_map'-service")

    assert manage(probe, ManageLifecycleNodes.Request.PAUSE)
    assert not is_active(probe)
    assert [state_of(probe, node) for node in MANAGED] == [State.PRIMARY_STATE_INACTIVE] * 2
    assert manage(probe, ManageLifecycleNodes.Request.RESUME)
    assert is_active(probe)
    assert [state_of(probe, node) for node in MANAGED] == [State.PRIMARY_STATE_ACTIVE] * 2

    assert manage(probe, ManageLifecycleNodes.Request.SHUTDOWN)
    assert not is_active(probe)
    assert [state_of(probe, node) for node in MANAGED] == [State.PRIMARY_STATE_FINALIZED] * 2
    manager.wait_for_output('Managed nodes have been shut down')
    for process in (map_server, saver):
        process.wait_for_output('Deactivating\n(.|\n)*Cleaning up\n(.|\n)*Shutting down')


def test_refused_command_lines_say_one_line(launch):
    started = {
        'no node_names': (launch('nav2_lifecycle_manager', 'lifecycle_manager'), 1,
                          r"Parameter 'node_names' is not set"),
        'wrong type': (launch('nav2_lifecycle_manager', 'lifecycle_manager', '--ros-args',
                              '-p', 'node_names:=map_server'), 1,
                       r"Parameter 'node_names' must be a list of strings, got 'map_server'"),
        '--occ': (launch(argv=[executable('nav2_map_server', 'map_saver_cli'), '--occ', 'abc']),
                  255, r"--occ should be followed by a number from 0 to 1, got 'abc'"),
        '--mode': (launch(argv=[executable('nav2_map_server', 'map_saver_cli'), '--mode', 'x']),
                   255, r"--mode should be followed by trinary, scale or raw, got 'x'"),
        '--fmt': (launch(argv=[executable('nav2_map_server', 'map_saver_cli'), '--fmt', 'gif']),
                  255, r"image format 'gif' is not one of bmp, pgm, png"),
        'unknown': (launch(argv=[executable('nav2_map_server', 'map_saver_cli'), '-x']),
                    255, r'Wrong argument: -x$'),
    }
    for what, (process, code, reason) in started.items():
        assert process.wait(timeout=30) == code, (what, process.output)
        problems = [line for line in process.output.splitlines()
                    if line.startswith(('[ERROR]', '[WARN]', 'Traceback'))]
        assert len(problems) == 1 and re.search(reason, problems[0]), (what, process.output)


def test_map_saver_cli_help(launch):
    process = launch(argv=[executable('nav2_map_server', 'map_saver_cli'), '--help'])
    assert process.wait(timeout=30) == 0
    assert process.output.startswith(
        'Usage:\n  map_saver_cli [arguments] [--ros-args ROS remapping args]\n\nArguments:\n'
        '  -h/--help\n  -t <map_topic>\n  -f <mapname>\n  --occ <threshold_occupied>\n'
        '  --free <threshold_free>\n  --fmt <image_format>\n'
        '  --mode trinary(default)/scale/raw\n\n'
        'NOTE: --ros-args should be passed at the end of command line\n')


def test_map_saver_server_launch_file_brings_the_saver_up(launch, ros_env, probe):
    run = launch(argv=['ros2', 'launch', 'nav2_map_server', 'map_saver_server.launch.py'],
                 env=ros_env)
    run.wait_for_output('Managed nodes are active', timeout=30)
    assert is_active(probe)
    assert state_of(probe, 'map_saver') == State.PRIMARY_STATE_ACTIVE
    # the launch file's parameters reached the node
    values = probe.call(GetParameters, '/map_saver/get_parameters', GetParameters.Request(
        names=['save_map_timeout', 'occupied_thresh_default'])).values
    assert [value.double_value for value in values] == [2.0, 0.65]
