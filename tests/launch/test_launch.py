"""`ros2 launch` and the launch API against real processes (shell and Python stand-ins).

Launch files are written per test; each runs through the real `ros2 launch` command and the
assertions read what a user sees: the launch's log lines, the prefixed child output, exit
codes, and which processes are still alive afterwards.
"""

from __future__ import annotations

import os
import re
import signal
import sys
import textwrap
import time
from pathlib import Path

from support import REPO, ros2

PID_LINE = re.compile(r'^\[INFO\] \[([\w.-]+)\]: process started with pid \[(\d+)\]$',
                      re.MULTILINE)


def write(path: Path, text: str) -> Path:
    path.write_text(textwrap.dedent(text))
    return path


def alive(pid: int) -> bool:
    """True while the process exists and is not a zombie."""
    try:
        state = Path(f'/proc/{pid}/stat').read_text().rsplit(')', 1)[1].split()[0]
    except (FileNotFoundError, ProcessLookupError):
        return False
    return state not in ('Z', 'X')


def error_lines(output: str) -> list[str]:
    return [line for line in output.splitlines()
            if line.startswith('[ERROR]') or 'error' in line.lower()]


def test_arguments_conditions_groups_and_environment(ros_env, tmp_path):
    launch_file = write(tmp_path / 'args.launch.py', '''
        from launch import LaunchDescription
        from launch.actions import (DeclareLaunchArgument, ExecuteProcess, GroupAction,
                                    LogInfo, SetEnvironmentVariable, SetLaunchConfiguration)
        from launch.conditions import IfCondition, UnlessCondition
        from launch.substitutions import (EnvironmentVariable, LaunchConfiguration,
                                          PythonExpression)

        def generate_launch_description():
            return LaunchDescription([
                DeclareLaunchArgument('greeting', default_value='hello',
                                      description='what to say'),
                DeclareLaunchArgument('loud', default_value='false', choices=['true', 'false']),
                LogInfo(msg=['greeting is ', LaunchConfiguration('greeting')]),
                LogInfo(msg='LOUD', condition=IfCondition(LaunchConfiguration('loud'))),
                LogInfo(msg='quiet', condition=UnlessCondition(LaunchConfiguration('loud'))),
                LogInfo(msg=['six is ', PythonExpression(['2 * 3'])]),
                GroupAction([
                    SetLaunchConfiguration('greeting', 'inside'),
                    SetEnvironmentVariable('LAUNCH_TEST_VAR', 'set in group'),
                    LogInfo(msg=['in group: ', LaunchConfiguration('greeting')]),
                    ExecuteProcess(cmd=['sh', '-c', 'echo "env: $LAUNCH_TEST_VAR"'],
                                   output='screen', name='envshow'),
                ]),
                LogInfo(msg=['after group: ', LaunchConfiguration('greeting'), ' ',
                             EnvironmentVariable('LAUNCH_TEST_VAR', default_value='unset')]),
            ])
        ''')
    shown = ros2(ros_env, 'launch', str(launch_file), '--show-args')
    assert shown.returncode == 0, shown.stderr
    assert shown.stdout == (
        "Arguments (pass arguments as '<name>:=<value>'):\n\n"
        "    'greeting':\n        what to say\n        (default: 'hello')\n\n"
        "    'loud':\n        One of: ['true', 'false']\n        (default: 'false')\n")
    run = ros2(ros_env, 'launch', str(launch_file), 'greeting:=hi', 'loud:=true')
    out = run.stdout
    assert run.returncode == 0, out + run.stderr
    assert re.match(r'\[INFO\] \[launch\]: All log files can be found below .+/\.ros/log/'
                    r'\d{4}-\d\d-\d\d-\d\d-\d\d-\d\d-\d{6}-[\w.-]+-\d+\n'
                    r'\[INFO\] \[launch\]: Default logging verbosity is set to INFO\n', out), out
    for line in ('[INFO] [launch.user]: greeting is hi', '[INFO] [launch.user]: LOUD',
                 '[INFO] [launch.user]: six is 6', '[INFO] [launch.user]: in group: inside',
                 '[envshow-1] env: set in group',
                 '[INFO] [launch.user]: after group: hi unset'):
        assert line in out.splitlines(), (line, out)
    assert 'quiet' not in out
    assert re.search(r'^\[INFO\] \[envshow-1\]: process has finished cleanly \[pid \d+\]$',
                     out, re.MULTILINE)
    bad_choice = ros2(ros_env, 'launch', str(launch_file), 'loud:=maybe')
    assert bad_choice.returncode == 1
    # Upstream's two lines: the argument's own logger, then the launch's.
    problem = ('Argument "loud" provided value "maybe" is not valid. Valid options are: '
               "['true', 'false']")
    assert error_lines(bad_choice.stdout + bad_choice.stderr) == [
        f'[ERROR] [launch.actions.declare_launch_argument]: {problem}',
        f'[ERROR] [launch]: Caught exception in launch (see debug for traceback): {problem}']


def test_include_with_arguments_and_this_launch_file_dir(ros_env, tmp_path):
    (tmp_path / 'sub').mkdir()
    write(tmp_path / 'sub' / 'child.launch.py', '''
        from launch import LaunchDescription
        from launch.actions import DeclareLaunchArgument, LogInfo
        from launch.substitutions import LaunchConfiguration, ThisLaunchFileDir

        def generate_launch_description():
            return LaunchDescription([
                DeclareLaunchArgument('who'),
                LogInfo(msg=['child says hi to ', LaunchConfiguration('who'), ' from ',
                             ThisLaunchFileDir()]),
            ])
        ''')
    parent = write(tmp_path / 'parent.launch.py', '''
        from launch import LaunchDescription
        from launch.actions import IncludeLaunchDescription, LogInfo
        from launch.launch_description_sources import PythonLaunchDescriptionSource
        from launch.substitutions import PathJoinSubstitution, ThisLaunchFileDir

        def generate_launch_description():
            return LaunchDescription([
                IncludeLaunchDescription(
                    PythonLaunchDescriptionSource(
                        PathJoinSubstitution([ThisLaunchFileDir(), 'sub', 'child.launch.py'])),
                    launch_arguments={'who': 'parent'}.items()),
                LogInfo(msg=['parent in ', ThisLaunchFileDir()]),
            ])
        ''')
    run = ros2(ros_env, 'launch', str(parent))
    assert run.returncode == 0, run.stdout + run.stderr
    assert f'[INFO] [launch.user]: child says hi to parent from {tmp_path}/sub' in run.stdout
    assert f'[INFO] [launch.user]: parent in {tmp_path}' in run.stdout
    # The child alone misses its required argument: one clear line, exit code 1.
    missing = ros2(ros_env, 'launch', str(tmp_path / 'sub' / 'child.launch.py'))
    assert missing.returncode == 1
    assert error_lines(missing.stdout + missing.stderr) == [
        '[ERROR] [launch]: Caught exception in launch (see debug for traceback): Included '
        "launch description missing required argument 'who' (description: 'no description "
        "given'), given: []"]


def test_event_handlers_timer_and_respawn(ros_env, tmp_path):
    launch_file = write(tmp_path / 'events.launch.py', '''
        from launch import LaunchDescription
        from launch.actions import (EmitEvent, ExecuteProcess, LogInfo, RegisterEventHandler,
                                    TimerAction)
        from launch.event_handlers import (OnExecutionComplete, OnProcessExit, OnProcessIO,
                                           OnProcessStart, OnShutdown)
        from launch.events import Shutdown
        from launch.substitutions import LocalSubstitution

        def generate_launch_description():
            talker = ExecuteProcess(cmd=['sh', '-c', 'echo spoken; exit 4'], name='talker')
            flaky = ExecuteProcess(cmd=['sh', '-c', 'exit 1'], name='flaky', respawn=True,
                                   respawn_delay=0.1, respawn_max_retries=2)
            sleeper = ExecuteProcess(cmd=['sleep', '30'])
            return LaunchDescription([
                talker, flaky,
                RegisterEventHandler(OnProcessStart(target_action=talker, on_start=[
                    LogInfo(msg='talker started')])),
                RegisterEventHandler(OnProcessIO(target_action=talker, on_stdout=lambda event:
                    LogInfo(msg='talker said ' + event.text.decode().strip()))),
                RegisterEventHandler(OnProcessExit(target_action=talker, on_exit=lambda event,
                    context: LogInfo(msg=f'talker exited with {event.returncode}'))),
                RegisterEventHandler(OnExecutionComplete(target_action=flaky, on_completion=[
                    LogInfo(msg='flaky gave up'), sleeper])),
                RegisterEventHandler(OnProcessStart(target_action=sleeper, on_start=[
                    TimerAction(period=0.3, actions=[
                        EmitEvent(event=Shutdown(reason='enough sleeping'))])])),
                RegisterEventHandler(OnShutdown(on_shutdown=[LogInfo(
                    msg=['asked to shut down: ', LocalSubstitution('event.reason')])])),
            ])
        ''')
    started = time.monotonic()
    run = ros2(ros_env, 'launch', str(launch_file))
    elapsed = time.monotonic() - started
    out = run.stdout
    assert run.returncode == 0, out + run.stderr
    lines = out.splitlines()
    for line in ('[INFO] [launch.user]: talker started',
                 '[INFO] [launch.user]: talker said spoken',
                 '[INFO] [launch.user]: talker exited with 4',
                 '[INFO] [launch.user]: flaky gave up',
                 '[INFO] [launch.user]: asked to shut down: enough sleeping'):
        assert line in lines, (line, out)
    # output='log' keeps stdout off the screen; the exit is reported as upstream does.
    assert '[talker-1] spoken' not in lines
    assert re.search(r"^\[ERROR\] \[talker-1\]: process has died \[pid \d+, exit code 4, "
                     r"cmd 'sh -c echo spoken; exit 4'\]\.$", out, re.MULTILINE)
    # respawned twice after the first run, under the same name
    assert len(re.findall(r'^\[INFO\] \[flaky-2\]: process started', out, re.MULTILINE)) == 3
    assert elapsed < 20, elapsed


def stop_scenario(tmp_path: Path) -> Path:
    """A child with a grandchild, and a child that ignores SIGINT (and has a grandchild)."""
    write(tmp_path / 'parent.py', '''
        import signal, subprocess, sys, time
        if sys.argv[1] == 'stubborn':
            signal.signal(signal.SIGINT, signal.SIG_IGN)
        child = subprocess.Popen(['sleep', '300'])
        print('grandchild', child.pid, flush=True)
        while True:
            time.sleep(1)
        ''')
    return write(tmp_path / 'stop.launch.py', f'''
        from launch import LaunchDescription
        from launch.actions import ExecuteProcess

        def generate_launch_description():
            return LaunchDescription([
                ExecuteProcess(cmd=[{sys.executable!r}, {str(tmp_path / 'parent.py')!r},
                                    'polite'], name='polite', output='screen'),
                ExecuteProcess(cmd=[{sys.executable!r}, {str(tmp_path / 'parent.py')!r},
                                    'stubborn'], name='stubborn', output='screen'),
            ])
        ''')


def test_ctrl_c_and_sigterm_stop_children_and_grandchildren(launch, ros_env, tmp_path):
    launch_file = stop_scenario(tmp_path)
    for stop_signal in (signal.SIGINT, signal.SIGTERM):
        run = launch(argv=['ros2', 'launch', str(launch_file), 'sigterm_timeout:=1'])
        run.wait_for_output(r'^\[stubborn-\d\] grandchild \d+$', timeout=30)
        run.wait_for_output(r'^\[polite-\d\] grandchild \d+$', timeout=30)
        pids = [int(pid) for _, pid in PID_LINE.findall(run.output)]
        pids += [int(p) for p in re.findall(r'grandchild (\d+)$', run.output, re.MULTILINE)]
        assert len(pids) == 4 and all(alive(pid) for pid in pids), run.output
        started = time.monotonic()
        if stop_signal == signal.SIGINT:
            os.killpg(run.popen.pid, signal.SIGINT)  # Ctrl-C reaches the terminal's group
        else:
            run.popen.send_signal(signal.SIGTERM)
        assert run.wait(timeout=20) == 0, run.output
        took = time.monotonic() - started
        out = run.output
        if stop_signal == signal.SIGINT:
            assert '[WARNING] [launch]: user interrupted with ctrl-c (SIGINT)' in out
        else:
            assert '[WARNING] [launch]: SIGTERM received, stopping every process' in out
        assert re.search(r"^\[ERROR\] \[stubborn-\d\]: process\[stubborn-\d\] failed to "
                         r"terminate '1' seconds after receiving 'SIGINT', escalating to "
                         r"'SIGTERM'$", out, re.MULTILINE), out
        assert re.search(r'^\[INFO\] \[polite-\d\]: process has finished cleanly', out,
                         re.MULTILINE) or re.search(r'^\[ERROR\] \[polite-\d\]: process has '
                                                    r'died \[pid \d+, exit code -2', out,
                                                    re.MULTILINE), out
        assert not [pid for pid in pids if alive(pid)], out
        assert took < 8, took


def test_bad_launch_files_give_one_clear_line(ros_env, tmp_path):
    syntax = write(tmp_path / 'syntax.launch.py', '''
        from launch import LaunchDescription
        def generate_launch_description(:
            return LaunchDescription([])
        ''')
    unknown_package = write(tmp_path / 'unknown_pkg.launch.py', '''
        from launch import LaunchDescription
        from launch_ros.actions import Node

        def generate_launch_description():
            return LaunchDescription([Node(package='no_such_pkg', executable='x')])
        ''')
    unsupported = write(tmp_path / 'unsupported.launch.py', '''
        from launch import LaunchDescription
        from launch_ros.actions import ComposableNodeContainer

        def generate_launch_description():
            return LaunchDescription([ComposableNodeContainer(
                name='container', namespace='', package='rclcpp_components',
                executable='component_container')])
        ''')
    unknown_keyword = write(tmp_path / 'keyword.launch.py', '''
        from launch import LaunchDescription
        from launch_ros.actions import Node

        def generate_launch_description():
            return LaunchDescription([Node(package='turtlesim', executable='turtlesim_node',
                                           composable=True)])
        ''')
    unknown_tag = write(tmp_path / 'tag.launch.xml', '<launch><rosparam file="x"/></launch>\n')
    cases = {
        (str(syntax),): 'Caught exception when trying to load file of format [py]: '
                        'SyntaxError: invalid syntax (syntax.launch.py, line 3)',
        (str(unknown_package),): "\"package 'no_such_pkg' not found, searching: [",
        (str(unsupported),): 'ComposableNodeContainer: composable nodes need a component '
                             'container (rclcpp_components), which this workspace does not '
                             'have; start the nodes with launch_ros.actions.Node instead',
        (str(unknown_keyword),): "TypeError: Action.__init__() got an unexpected keyword "
                                 "argument 'composable'",
        (str(unknown_tag),): 'Caught exception when trying to load file of format [xml]: '
                             'RuntimeError: Unrecognized entity of the type: rosparam',
        ('no_such_pkg', 'x.launch.py'): "Package 'no_such_pkg' not found: \"package "
                                        "'no_such_pkg' not found, searching: [",
        ('turtlesim', 'nope.launch.py'): "file 'nope.launch.py' was not found in the share "
                                         "directory of package 'turtlesim' which is at '",
        (str(syntax), 'bad-arg'): "malformed launch argument 'bad-arg', expected format "
                                  "'<name>:=<value>'",
    }
    for args, expected in cases.items():
        run = ros2(ros_env, 'launch', *args)
        both = run.stdout + run.stderr
        assert run.returncode == 1, (args, both)
        assert 'Traceback' not in both, both
        errors = [line for line in both.splitlines()
                  if not line.startswith('[INFO] [launch]: ')]
        assert len(errors) == 1 and expected in errors[0], (args, both)


def test_print_shows_the_description_tree(ros_env):
    multisim = REPO / 'src' / 'turtlesim' / 'launch' / 'multisim.launch.py'
    run = ros2(ros_env, 'launch', '--print', str(multisim))
    assert run.returncode == 0, run.stderr
    lines = run.stdout.splitlines()
    assert re.match(r'^<launch\.launch_description\.LaunchDescription object at 0x[0-9a-f]+>$',
                    lines[0])
    assert lines[1:] == [
        "├── ExecuteProcess(cmd=[ExecInPkg(pkg='turtlesim', exec='turtlesim_node'), "
        "'--ros-args'], cwd=None, env=None, shell=False)",
        "└── ExecuteProcess(cmd=[ExecInPkg(pkg='turtlesim', exec='turtlesim_node'), "
        "'--ros-args'], cwd=None, env=None, shell=False)",
    ]
