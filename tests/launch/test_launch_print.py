"""`ros2 launch --print` and `describe()` read as upstream Jazzy's.

The expected texts below are what upstream's launch and launch_ros (branch jazzy) print for
the same launch files and entities, written down here; object addresses differ from run to
run and are compared as `0x…`. Before these tests FindPackageShare described itself as
`Pkg(pkg=...)` and OnStateTransition as `matcher='None', handler='None'`.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import pytest
from ament_index_python.packages import get_package_share_directory

import launch
from launch import actions, conditions, event_handlers, substitutions
from launch_ros import actions as ros_actions
from launch_ros import event_handlers as ros_event_handlers
from launch_ros import substitutions as ros_substitutions
from support import ros2, ros2_side_by_side

ADDRESS = re.compile(r'0x[0-9a-f]+')


def unaddressed(text: str) -> str:
    return ADDRESS.sub('0x…', text)


# A launch file with what real robots' files use: FindPackageShare in a PathJoinSubstitution,
# a LifecycleNode driven by OnStateTransition, OnProcessStart/Exit, IfCondition, OnShutdown.
HANDLERS_LAUNCH = '''
import lifecycle_msgs.msg
from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, EmitEvent, ExecuteProcess, LogInfo,
                            RegisterEventHandler, TimerAction)
from launch.conditions import IfCondition, UnlessCondition
from launch.event_handlers import OnProcessExit, OnProcessStart, OnShutdown
from launch.events import Shutdown
from launch.substitutions import (EnvironmentVariable, LaunchConfiguration,
                                  PathJoinSubstitution, PythonExpression)
from launch_ros.actions import LifecycleNode, Node
from launch_ros.event_handlers import OnStateTransition
from launch_ros.events.lifecycle import ChangeState
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    talker = LifecycleNode(package='lifecycle', executable='lifecycle_talker',
                           name='lc_talker', namespace='', output='screen')
    listener = Node(package='lifecycle', executable='lifecycle_listener',
                    condition=IfCondition(LaunchConfiguration('listen')))
    counter = ExecuteProcess(cmd=['seq', '3'], name='counter')
    activate = EmitEvent(event=ChangeState(
        lifecycle_node_matcher=lambda action: action is talker,
        transition_id=lifecycle_msgs.msg.Transition.TRANSITION_ACTIVATE))
    return LaunchDescription([
        DeclareLaunchArgument('listen', default_value='true'),
        LogInfo(msg=['Icon: ', PathJoinSubstitution(
            [FindPackageShare('turtlesim'), 'images', 'humble.png'])]),
        LogInfo(msg=PythonExpression(["'", EnvironmentVariable('USER', default_value='me'),
                                      "'.upper()"]),
                condition=UnlessCondition('false')),
        talker,
        listener,
        counter,
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=talker, goal_state='inactive',
            entities=[LogInfo(msg='talker is inactive: activating'), activate])),
        RegisterEventHandler(OnStateTransition(
            entities=[LogInfo(msg='some lifecycle node changed state')])),
        RegisterEventHandler(OnProcessStart(target_action=counter,
                                            on_start=[LogInfo(msg='counting')])),
        RegisterEventHandler(OnProcessExit(target_action=counter,
                                           on_exit=[LogInfo(msg='counted'),
                                                    EmitEvent(event=Shutdown())])),
        RegisterEventHandler(OnShutdown(on_shutdown=[LogInfo(msg='bye')])),
        TimerAction(period=2.0, actions=[LogInfo(msg='two seconds')]),
    ])
'''

HANDLERS_PRINTED = """\
<launch.launch_description.LaunchDescription object at 0x…>
├── Action('<launch.actions.declare_launch_argument.DeclareLaunchArgument object at 0x…>')
├── LogInfo('Icon: ' + PathJoin('FindPackageShare(pkg='turtlesim') + 'images' + 'humble.png''))
├── LogInfo(PythonExpr(''' + EnvVar('USER') + ''.upper()', ['math']))
├── ExecuteProcess(cmd=[ExecInPkg(pkg='lifecycle', exec='lifecycle_talker'), '--ros-args', \
'-r', LocalVar('node name')], cwd=None, env=None, shell=False)
├── ExecuteProcess(cmd=[ExecInPkg(pkg='lifecycle', exec='lifecycle_listener'), '--ros-args'], \
cwd=None, env=None, shell=False)
├── ExecuteProcess(cmd=['seq', '3'], cwd=None, env=None, shell=False)
├── RegisterEventHandler('<launch_ros.event_handlers.on_state_transition.OnStateTransition \
object at 0x…>'):
│   ├── OnStateTransition(matcher='event == StateTransition and event.action == \
LifecycleNode(0x…)', handler='<actions>', handle_once=False)
│       ├── LogInfo('talker is inactive: activating')
│       └── EmitEvent(event='launch_ros.events.lifecycle.ChangeState')
├── RegisterEventHandler('<launch_ros.event_handlers.on_state_transition.OnStateTransition \
object at 0x…>'):
│   ├── OnStateTransition(matcher='event == StateTransition', handler='<actions>', \
handle_once=False)
│       └── LogInfo('some lifecycle node changed state')
├── RegisterEventHandler('<launch.event_handlers.on_process_start.OnProcessStart object at \
0x…>'):
│   ├── OnProcessStart(matcher='event == ProcessStarted and ExecuteProcess(event.action)', \
handler='<actions>', handle_once=False)
│       └── LogInfo('counting')
├── RegisterEventHandler('<launch.event_handlers.on_process_exit.OnProcessExit object at \
0x…>'):
│   ├── OnProcessExit(matcher='event == ProcessExited and ExecuteLocal(event.action)', \
handler='<actions>', handle_once=False)
│       ├── LogInfo('counted')
│       └── EmitEvent(event='launch.events.Shutdown')
├── RegisterEventHandler('<launch.event_handlers.on_shutdown.OnShutdown object at 0x…>'):
│   └── OnShutdown(matcher='event issubclass of launch.events.Shutdown', \
handler='<function gen_handler.<locals>.handler at 0x…>', handle_once=False)
└── Action('<launch.actions.timer_action.TimerAction object at 0x…>')
"""

DECLARE = "Action('<launch.actions.declare_launch_argument.DeclareLaunchArgument object at 0x…>')"

# The workspace's robot launch files, as upstream's launch prints them.
ROBOTS_PRINTED = {
    ('diffbot_bringup', 'diffbot_sim.launch.py'): '\n'.join([
        '<launch.launch_description.LaunchDescription object at 0x…>',
        '{declares}',
        "├── ExecuteProcess(cmd=[ExecInPkg(pkg='mujoco_sim', exec='mujoco_sim'), '--ros-args'], "
        'cwd=None, env=None, shell=False)',
        "├── ExecuteProcess(cmd=[ExecInPkg(pkg='robot_state_publisher', "
        "exec='robot_state_publisher'), '--ros-args'], cwd=None, env=None, shell=False)",
        "└── ExecuteProcess(cmd=[ExecInPkg(pkg='rviz2', exec='rviz2'), '-d', "
        "PathJoin('FindPackageShare(pkg='diffbot_bringup') + 'rviz' + 'diffbot.rviz''), "
        "'--ros-args', '-r', LocalVar('node name')], cwd=None, env=None, shell=False)", '']),
    ('lifecycle', 'lifecycle_demo_launch.py'): '\n'.join([
        '<launch.launch_description.LaunchDescription object at 0x…>',
        "├── ExecuteProcess(cmd=[ExecInPkg(pkg='lifecycle', exec='lifecycle_talker'), "
        "'--ros-args', '-r', LocalVar('node name')], cwd=None, env=None, shell=False)",
        "├── ExecuteProcess(cmd=[ExecInPkg(pkg='lifecycle', exec='lifecycle_listener'), "
        "'--ros-args'], cwd=None, env=None, shell=False)",
        "└── ExecuteProcess(cmd=[ExecInPkg(pkg='lifecycle', exec='lifecycle_service_client'), "
        "'--ros-args'], cwd=None, env=None, shell=False)", '']),
    ('urdf_tutorial', 'display.launch.py'): '\n'.join([
        '<launch.launch_description.LaunchDescription object at 0x…>',
        '{declares}',
        "├── ExecuteProcess(cmd=[ExecInPkg(pkg='robot_state_publisher', "
        "exec='robot_state_publisher'), '--ros-args'], cwd=None, env=None, shell=False)",
        "├── ExecuteProcess(cmd=[ExecInPkg(pkg='joint_state_publisher_gui', "
        "exec='joint_state_publisher_gui'), '--ros-args'], cwd=None, env=None, shell=False)",
        "├── ExecuteProcess(cmd=[ExecInPkg(pkg='joint_state_publisher', "
        "exec='joint_state_publisher'), '--ros-args'], cwd=None, env=None, shell=False)",
        "└── ExecuteProcess(cmd=[ExecInPkg(pkg='rviz2', exec='rviz2'), '-d', "
        "LaunchConfig('rvizconfig'), '--ros-args', '-r', LocalVar('node name')], cwd=None, "
        'env=None, shell=False)', '']),
}


def test_print_of_a_launch_file_with_event_handlers(tmp_path: Path, ros_env) -> None:
    path = tmp_path / 'handlers.launch.py'
    path.write_text(HANDLERS_LAUNCH)
    done = ros2(ros_env, 'launch', '--print', str(path))
    assert done.returncode == 0, done.stderr
    assert unaddressed(done.stdout) == HANDLERS_PRINTED, done.stdout
    # The matcher names the LifecycleNode the handler was given, by its id, as upstream.
    assert re.search(r"matcher='event == StateTransition and event\.action == "
                     r"LifecycleNode\(0x[0-9a-f]+\)'", done.stdout)


def test_print_of_the_robots_launch_files(ros_env) -> None:
    runs = ros2_side_by_side(ros_env, *[['launch', '--print', package, name]
                                        for package, name in ROBOTS_PRINTED])
    for (key, expected), done in zip(ROBOTS_PRINTED.items(), runs, strict=True):
        assert done.returncode == 0, (key, done.stderr)
        # One line per launch argument the file declares (their number changes as the
        # files grow; upstream prints each the same way).
        source = next(Path(get_package_share_directory(key[0])).rglob(key[1])).read_text()
        declares = '\n'.join([f'├── {DECLARE}'] * source.count('DeclareLaunchArgument('))
        assert unaddressed(done.stdout) == expected.replace('{declares}', declares), (
            key, done.stdout)


def repr_text(module: str, name: str) -> str:
    return f'<{module}.{name} object at 0x…>'


def test_substitutions_describe_themselves_as_upstreams() -> None:
    config = substitutions.LaunchConfiguration('x')
    pair = ("([<launch.substitutions.launch_configuration.LaunchConfiguration object at 0x…>] "
            "[<launch.substitutions.text_substitution.TextSubstitution object at 0x…>])")
    cases = [
        (substitutions.TextSubstitution(text='a'), "'a'"),
        (substitutions.LaunchConfiguration('x', default='d'), "LaunchConfig('x')"),
        (substitutions.EnvironmentVariable('HOME', default_value='h'), "EnvVar('HOME')"),
        (substitutions.FindExecutable(name='ls'), "FindExec('ls')"),
        (substitutions.PythonExpression(['1 + ', config]),
         "PythonExpr('1 + ' + LaunchConfig('x'), ['math'])"),
        (substitutions.Command(['echo ', config]), "Command('echo ' + LaunchConfig('x'))"),
        (substitutions.AnonName('n'), "AnonName('n')"),
        (substitutions.LocalSubstitution('event.returncode', description='rc'), "LocalVar('rc')"),
        (substitutions.PathJoinSubstitution(['a', config]), "PathJoin(''a' + LaunchConfig('x')')"),
        (substitutions.ThisLaunchFile(), 'ThisLaunchFile()'),
        (substitutions.ThisLaunchFileDir(), 'ThisLaunchFileDir()'),
        (substitutions.LaunchLogDir(), 'LaunchLogDir()'),
        (substitutions.FileContent(['/etc/hostname']), "FileContent('/etc/hostname')"),
        (substitutions.NotSubstitution(config), 'NotSubstitution([<launch.substitutions.'
         'launch_configuration.LaunchConfiguration object at 0x…>])'),
        (substitutions.AndSubstitution(config, 'true'), 'AndSubstitution' + pair),
        # Upstream's OrSubstitution says AndSubstitution: --print shows that text.
        (substitutions.OrSubstitution(config, 'true'), 'AndSubstitution' + pair),
        (substitutions.AnySubstitution(config, 'true'), 'AnySubstitution' + pair),
        (substitutions.AllSubstitution(config, 'true'), 'AllSubstitution' + pair),
        (substitutions.EqualsSubstitution(config, 'true'), 'EqualsSubstitution' + pair),
        (substitutions.NotEqualsSubstitution(config, 'true'), 'NotEqualsSubstitution' + pair),
        (ros_substitutions.FindPackageShare('turtlesim'), "FindPackageShare(pkg='turtlesim')"),
        (ros_substitutions.FindPackagePrefix('turtlesim'), "FindPackagePrefix(pkg='turtlesim')"),
        (ros_substitutions.ExecutableInPackage('talker', 'demo_nodes_py'),
         "ExecInPkg(pkg='demo_nodes_py', exec='talker')"),
        (ros_substitutions.Parameter('p'), "Parameter(name='p')"),
    ]
    for substitution, expected in cases:
        assert unaddressed(substitution.describe()) == expected, type(substitution)


def test_conditions_and_actions_describe_themselves_as_upstreams() -> None:
    config = substitutions.LaunchConfiguration('x')
    shown: list[tuple[Any, str]] = [
        (conditions.IfCondition(config), repr_text('launch.conditions.if_condition',
                                                   'IfCondition')),
        (conditions.UnlessCondition(config), repr_text('launch.conditions.unless_condition',
                                                       'UnlessCondition')),
        (launch.Condition(predicate=lambda _context: True),
         repr_text('launch.condition', 'Condition')),
        (actions.DeclareLaunchArgument('x', default_value='1'),
         repr_text('launch.actions.declare_launch_argument', 'DeclareLaunchArgument')),
        (actions.ExecuteProcess(cmd=['sleep', '1']),
         repr_text('launch.actions.execute_process', 'ExecuteProcess')),
        (actions.IncludeLaunchDescription(
            launch.LaunchDescriptionSource(launch.LaunchDescription())),
         repr_text('launch.actions.include_launch_description', 'IncludeLaunchDescription')),
        (actions.LogInfo(msg='hi'), repr_text('launch.actions.log_info', 'LogInfo')),
        (actions.GroupAction([]), repr_text('launch.actions.group_action', 'GroupAction')),
        (actions.TimerAction(period=1.0, actions=[]), 'TimerAction(period=1.0, '
                                                       'actions=<actions>)'),
        (ros_actions.Node(package='demo_nodes_py', executable='talker'),
         repr_text('launch_ros.actions.node', 'Node')),
        (ros_actions.LifecycleNode(package='lifecycle', executable='lifecycle_talker',
                                   name='lc_talker', namespace=''),
         repr_text('launch_ros.actions.lifecycle_node', 'LifecycleNode')),
        (ros_actions.ROSTimer(period=1.0, actions=[]), 'ROSTimer(period=1.0, '
                                                         'actions=<actions>)'),
        (ros_actions.SetParameter('a', 1), repr_text('launch_ros.actions.set_parameter',
                                                     'SetParameter')),
    ]
    for entity, expected in shown:
        assert unaddressed(entity.describe()) == expected, type(entity)
    guarded = actions.LogInfo(msg='x', condition=conditions.IfCondition('true'))
    assert [(unaddressed(text), len(list(entities))) for text, entities in
            guarded.describe_conditional_sub_entities()] == [
        ('Conditionally included by ' + repr_text('launch.actions.log_info', 'LogInfo'), 0)]
    timer = actions.TimerAction(period=2.0, actions=[actions.LogInfo(msg='t')])
    assert [(text, len(list(entities))) for text, entities in
            timer.describe_conditional_sub_entities()] == [
        ('2.0 seconds pass without being canceled', 1)]


def test_event_handlers_describe_themselves_as_upstreams() -> None:
    process = actions.ExecuteProcess(cmd=['sleep', '1'])
    talker = ros_actions.LifecycleNode(package='lifecycle', executable='lifecycle_talker',
                                       name='lc_talker', namespace='')
    log = [actions.LogInfo(msg='x')]
    cases = [
        (event_handlers.OnProcessExit(target_action=process, on_exit=log),
         "OnProcessExit(matcher='event == ProcessExited and ExecuteLocal(event.action)', "
         "handler='<actions>', handle_once=False)", 1),
        (event_handlers.OnProcessStart(target_action=process, on_start=log),
         "OnProcessStart(matcher='event == ProcessStarted and ExecuteProcess(event.action)', "
         "handler='<actions>', handle_once=False)", 1),
        (event_handlers.OnProcessIO(target_action=process, on_stdout=lambda _event: None),
         "OnProcessIO(matcher='event == ProcessIO and ExecuteLocal(event.action)', "
         "handler='<function OnProcessIO.__init__.<locals>.handle at 0x…>', "
         'handle_once=False)', 0),
        (event_handlers.OnExecutionComplete(target_action=process, on_completion=log),
         "OnExecutionComplete(matcher='event == ExecutionComplete and Action(event.action)', "
         "handler='<actions>', handle_once=False)", 1),
        (event_handlers.OnShutdown(on_shutdown=log),
         "OnShutdown(matcher='event issubclass of launch.events.Shutdown', "
         "handler='<function gen_handler.<locals>.handler at 0x…>', handle_once=False)", 0),
        (launch.EventHandler(matcher=lambda _event: True, entities=log),
         "EventHandler(matcher='None', handler='None', handle_once=False)", 1),
        (ros_event_handlers.OnStateTransition(entities=log),
         "OnStateTransition(matcher='event == StateTransition', handler='<actions>', "
         'handle_once=False)', 1),
    ]
    for handler, expected, count in cases:
        text, entities = handler.describe()
        assert (unaddressed(text), len(entities)) == (expected, count), type(handler)
    targeted = ros_event_handlers.OnStateTransition(target_lifecycle_node=talker,
                                                     goal_state='inactive', entities=log)
    assert targeted.describe()[0] == (
        "OnStateTransition(matcher='event == StateTransition and event.action == "
        f"LifecycleNode({hex(id(talker))})', handler='<actions>', handle_once=False)")


@pytest.mark.parametrize('handler', ['OnProcessExit', 'OnShutdown'])
def test_a_handler_given_a_function_names_it(handler: str) -> None:
    def on_event(_event: Any, _context: Any) -> None:
        return None
    made = (event_handlers.OnProcessExit(on_exit=on_event) if handler == 'OnProcessExit'
            else event_handlers.OnShutdown(on_shutdown=on_event))
    text = unaddressed(made.describe()[0])
    assert "handler='<function test_a_handler_given_a_function_names_it.<locals>.on_event at " \
           "0x…>'" in text, text
