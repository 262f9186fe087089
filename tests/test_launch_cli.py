"""`ros2 launch` options as upstream's: --show-args with the arguments of included files,
--launch-prefix / --launch-prefix-filter, --debug, and one-line errors for bad options."""

from __future__ import annotations

import re
import textwrap
from pathlib import Path

from support import ros2


def write(path: Path, text: str) -> Path:
    path.write_text(textwrap.dedent(text))
    return path


def test_show_args_lists_arguments_of_included_files(ros_env, tmp_path):
    write(tmp_path / 'inner.launch.xml', '''
        <launch>
          <arg name="world" default="empty" description="Which world">
            <choice value="empty"/>
            <choice value="maze"/>
          </arg>
        </launch>
        ''')
    outer = write(tmp_path / 'outer.launch.py', '''
        import os

        from launch import LaunchDescription
        from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
        from launch.conditions import IfCondition
        from launch.substitutions import LaunchConfiguration

        def generate_launch_description():
            return LaunchDescription([
                DeclareLaunchArgument('rate', default_value='10', description='Hz'),
                DeclareLaunchArgument('gui', default_value='true',
                                      condition=IfCondition(LaunchConfiguration('rate'))),
                IncludeLaunchDescription(
                    os.path.join(os.path.dirname(__file__), 'inner.launch.xml')),
            ])
        ''')
    run = ros2(ros_env, 'launch', '--show-args', str(outer))
    assert run.returncode == 0, run.stdout + run.stderr
    assert run.stdout == textwrap.dedent('''\
        Arguments (pass arguments as '<name>:=<value>'):

            'rate':
                Hz
                (default: '10')

            'gui':*
                no description given
                (default: 'true')

            'world':
                Which world. Valid choices are: ['empty', 'maze']
                (default: 'empty')

        * argument(s) which are only used if specific conditions occur
        ''')


def test_launch_prefix_filter_and_debug(ros_env, tmp_path):
    launch_file = write(tmp_path / 'two.launch.py', '''
        from launch import LaunchDescription
        from launch.actions import ExecuteProcess

        def generate_launch_description():
            return LaunchDescription([
                ExecuteProcess(cmd=['true'], name='first', output='screen'),
                ExecuteProcess(cmd=['sh', '-c', 'echo plain'], name='second', output='screen'),
            ])
        ''')
    run = ros2(ros_env, 'launch', '--debug', '--launch-prefix', 'echo wrapped',
               '--launch-prefix-filter', '^true$', str(launch_file))
    assert run.returncode == 0, run.stdout + run.stderr
    lines = run.stdout.splitlines()
    assert '[INFO] [launch]: Default logging verbosity is set to DEBUG' in lines
    # The prefix goes in front of the matching executable only.
    assert re.search(r'^\[first-\d+\] wrapped true$', run.stdout, re.MULTILINE), run.stdout
    assert re.search(r'^\[second-\d+\] plain$', run.stdout, re.MULTILINE), run.stdout
    assert any(line.startswith('[DEBUG] [launch') for line in lines), run.stdout

    lone_filter = ros2(ros_env, 'launch', '--launch-prefix-filter', 'x', str(launch_file))
    assert lone_filter.returncode == 1
    assert '--launch-prefix must be specified if --launch-prefix-filter is provided' in (
        lone_filter.stdout + lone_filter.stderr)
    assert 'Traceback' not in lone_filter.stdout + lone_filter.stderr


def test_screen_and_log_formats_from_the_environment(ros_env, tmp_path):
    launch_file = write(tmp_path / 'say.launch.xml', '''
        <launch><log message="formatted"/></launch>
        ''')
    env = {**ros_env, 'OVERRIDE_LAUNCH_SCREEN_FORMAT': '{levelname}|{name}|{message}',
           'OVERRIDE_LAUNCH_LOG_FORMAT': 'file:{message}', 'ROS_LOG_DIR': str(tmp_path / 'l')}
    run = ros2(env, 'launch', str(launch_file))
    assert run.returncode == 0, run.stdout + run.stderr
    assert 'INFO|launch.user|formatted' in run.stdout.splitlines(), run.stdout
    (log_file,) = [path for path in (tmp_path / 'l').glob('*/launch.log')
                   if path.parent.name != 'latest']
    assert 'file:formatted' in log_file.read_text().splitlines()
    assert (tmp_path / 'l' / 'latest').resolve() == log_file.parent
