"""The launch Python API as upstream's: module paths, substitutions, front ends read from
streams, events emitted from another thread, shutdown, launch arguments of included files.

Each test runs a real LaunchService (real child processes where a process is involved) in
this pytest process and reads what a user sees: the log lines on the screen, the files in
the log directory, the values the substitutions give.
"""

from __future__ import annotations

import importlib
import io
import os
import re
import sys
import threading
import time
import xml.etree.ElementTree as ElementTree

import launch.logging
import pytest
from launch.actions import (
    DeclareLaunchArgument,
    ExecuteLocal,
    ExecuteProcess,
    GroupAction,
    IncludeLaunchDescription,
    LogInfo,
    RegisterEventHandler,
    SetEnvironmentVariable,
    Shutdown,
    TimerAction,
)
from launch.descriptions import Executable
from launch.event_handlers import OnProcessExit, OnShutdown
from launch.events import IncludeLaunchDescription as IncludeEvent
from launch.events import Shutdown as ShutdownEvent
from launch.events.process import ProcessExited
from launch.frontend import Parser
from launch.launch_description_sources import LaunchDescriptionSource
from launch.substitutions import (
    AllSubstitution,
    AndSubstitution,
    AnySubstitution,
    Command,
    EnvironmentVariable,
    EqualsSubstitution,
    FileContent,
    IfElseSubstitution,
    LaunchConfiguration,
    LaunchLogDir,
    NotEqualsSubstitution,
    NotSubstitution,
    OrSubstitution,
    PythonExpression,
    SubstitutionFailure,
)
from launch_xml.entity import Entity as XmlEntity

from launch import Event, LaunchContext, LaunchDescription, LaunchService

UPSTREAM_PATHS = {
    'launch.actions.execute_process': 'ExecuteProcess',
    'launch.actions.execute_local': 'ExecuteLocal',
    'launch.actions.emit_event': 'EmitEvent',
    'launch.actions.opaque_function': 'OpaqueFunction',
    'launch.actions.shutdown_action': 'Shutdown',
    'launch.actions.timer_action': 'TimerAction',
    'launch.event_handlers.on_process_exit': 'OnProcessExit',
    'launch.event_handlers.on_process_io': 'OnProcessIO',
    'launch.event_handlers.on_process_start': 'OnProcessStart',
    'launch.event_handlers.on_shutdown': 'OnShutdown',
    'launch.events.process.process_exited': 'ProcessExited',
    'launch.events.shutdown': 'Shutdown',
    'launch.substitutions.if_else_substitution': 'IfElseSubstitution',
    'launch.substitutions.equals_substitution': 'EqualsSubstitution',
    'launch.substitutions.launch_configuration': 'LaunchConfiguration',
    'launch.utilities': 'normalize_to_list_of_substitutions',
    'launch.utilities.type_utils': 'perform_typed_substitution',
    'launch.descriptions': 'Executable',
    'launch.invalid_launch_file_error': 'InvalidLaunchFileError',
}


def run(description: LaunchDescription, **options: object) -> int:
    service = LaunchService(**options)
    service.include_launch_description(description)
    return service.run()


def user_lines(text: str) -> list[str]:
    prefix = '[INFO] [launch.user]: '
    return [line[len(prefix):] for line in text.splitlines() if line.startswith(prefix)]


def test_upstream_module_paths_import():
    for module, name in UPSTREAM_PATHS.items():
        assert hasattr(importlib.import_module(module), name), (module, name)
    for grab_bag in ('launch.actions.simple', 'launch.substitutions.basic'):
        with pytest.raises(ImportError):
            importlib.import_module(grab_bag)


def test_event_names_are_upstreams():
    assert Event().name == 'launch.Event'
    assert ShutdownEvent().name == 'launch.events.Shutdown'
    assert ProcessExited.name == 'launch.events.process.ProcessExited'


def test_comparison_and_boolean_substitutions():
    context = LaunchContext()
    context.launch_configurations['mode'] = 'sim'
    mode = LaunchConfiguration('mode')
    cases = [
        (EqualsSubstitution(mode, 'sim'), 'true'),
        (EqualsSubstitution('1', True), 'true'),      # booleans compare as booleans
        (EqualsSubstitution('2.0', 2), 'true'),       # numbers as numbers
        (NotEqualsSubstitution(mode, 'real'), 'true'),
        (IfElseSubstitution(EqualsSubstitution(mode, 'sim'), 'fake', 'real'), 'fake'),
        (IfElseSubstitution('false', else_value='only else'), 'only else'),
        (AndSubstitution('true', '0'), 'false'),
        (OrSubstitution('false', '1'), 'true'),
        (NotSubstitution('false'), 'true'),
        (AnySubstitution('false', 'false', 'true'), 'true'),
        (AllSubstitution('true', '1', 'false'), 'false'),
    ]
    for substitution, expected in cases:
        assert substitution.perform(context) == expected, substitution.describe()
    with pytest.raises(SubstitutionFailure):
        AndSubstitution('maybe', 'true').perform(context)
    with pytest.raises(RuntimeError, match='One of if_value and else_value'):
        IfElseSubstitution('true')


def test_python_expression_modules_and_implicit_math():
    context = LaunchContext()
    assert PythonExpression(['sqrt(16) + pi * 0']).perform(context) == '4.0'
    assert PythonExpression(['math.floor(2.7)']).perform(context) == '2'
    assert PythonExpression(['os.path.join("a", "b")'], python_modules=['os']).perform(
        context) == 'a/b'
    with pytest.raises(NameError):
        PythonExpression(['sqrt(4)'], python_modules=['os']).perform(context)


def test_file_content_command_and_log_dir(tmp_path):
    context = LaunchContext()
    note = tmp_path / 'note.txt'
    note.write_text('robot_description text\n')
    assert FileContent(str(note)).perform(context) == 'robot_description text\n'
    with pytest.raises(SubstitutionFailure, match=r'^File not found: '):
        FileContent(str(tmp_path / 'missing.txt')).perform(context)
    assert Command(['echo ', 'made by a command']).perform(context) == 'made by a command\n'
    with pytest.raises(SubstitutionFailure, match=r'^file not found: '):
        Command('no-such-executable-here --flag').perform(context)
    assert os.path.isdir(LaunchLogDir().perform(context))


def test_xml_and_yaml_read_from_streams(capsys):
    xml = io.StringIO(
        '<launch>'
        '<arg name="speed" default="2"/>'
        '<let name="fast" value="$(if $(equals $(var speed) 2.0) yes no)"/>'
        '<log message="fast=$(var fast) area=$(eval \'$(var speed) ** 2\')"/>'
        '</launch>')
    yaml = io.StringIO(
        'launch:\n'
        '- let: {name: robot, value: "$(not-equals a b)"}\n'
        '- log: {message: "differ=$(var robot)"}\n')
    for stream in (xml, yaml):
        root, parser = Parser.load(stream)
        assert run(parser.parse_description(root)) == 0
    assert user_lines(capsys.readouterr().out) == ['fast=yes area=4', 'differ=true']


def test_frontend_timers_lists_and_nested_quotes(capsys, monkeypatch):
    monkeypatch.setenv('API_TEST_DEFAULT', 'dflt')
    xml = io.StringIO(
        '<launch>'
        '<let name="wait" value="0.1"/>'
        '<timer period="$(var wait)"><log message="timer fired"/></timer>'
        '<log message="$(env \'$(var wait)_unset\' \'$(env API_TEST_DEFAULT)_x\')"/>'
        '<executable cmd="echo \'a  b\' c" output="screen"/>'
        '</launch>')
    root, parser = Parser.load(xml)
    assert run(parser.parse_description(root)) == 0
    out = capsys.readouterr().out
    assert user_lines(out) == ['dflt_x', 'timer fired']
    assert re.search(r'^\[echo-\d+\] a  b c$', out, re.MULTILINE), out
    # `name-sep` makes a list of an XML attribute
    entity = XmlEntity(ElementTree.fromstring('<x v="1;2;3" v-sep=";"/>'))
    assert entity.get_attr('v', data_type=list[int]) == [1, 2, 3]
    entity.assert_entity_completely_parsed()


def test_execute_local_environment_and_callable_targets(capsys, monkeypatch):
    monkeypatch.setenv('API_TEST_OUTER', 'outer')
    script = 'import os; print(os.environ.get("API_TEST_OUTER"), os.environ["API_TEST_MORE"])'
    clean = ExecuteLocal(process_description=Executable(
        cmd=[sys.executable, '-c', script], env={'API_TEST_MORE': 'given'}), output='screen')
    inherit = ExecuteLocal(process_description=Executable(
        cmd=[sys.executable, '-c', script], additional_env={'API_TEST_MORE': 'added'}),
        output='screen')
    assert run(LaunchDescription([
        RegisterEventHandler(OnProcessExit(
            target_action=lambda action: action is clean,
            on_exit=[LogInfo(msg=['clean exited, outer is ',
                                  EnvironmentVariable('API_TEST_OUTER')])])),
        GroupAction([SetEnvironmentVariable('API_TEST_OUTER', 'in group'), clean]),
        inherit,
    ])) == 0
    out = capsys.readouterr().out
    assert '] None given' in out and '] outer added' in out, out
    # the group's change was undone when it ended (the environment is os.environ)
    assert user_lines(out) == ['clean exited, outer is outer']
    assert os.environ['API_TEST_OUTER'] == 'outer'
    assert clean.process_details['env'] == {'API_TEST_MORE': 'given'}


def test_description_included_from_another_thread(capsys):
    """launch_testing's tools start processes by emitting IncludeLaunchDescription from the
    test's thread; the running launch must pick it up."""
    service = LaunchService()
    service.include_launch_description(LaunchDescription([LogInfo(msg='started')]))

    def from_other_thread() -> None:
        deadline = time.monotonic() + 10
        while service.event_loop is None and time.monotonic() < deadline:
            time.sleep(0.01)
        service.emit_event(IncludeEvent(LaunchDescription([
            ExecuteProcess(cmd=[sys.executable, '-c', 'print("from the thread")'],
                           name='late', output='screen'),
            RegisterEventHandler(OnShutdown(on_shutdown=[LogInfo(msg='stopping')])),
        ])))
        time.sleep(1.0)
        service.shutdown()

    helper = threading.Thread(target=from_other_thread)
    helper.start()
    code = service.run(shutdown_when_idle=False)
    helper.join(timeout=10)
    out = capsys.readouterr().out
    assert code == 0
    assert '[late-' in out and '] from the thread' in out, out
    assert user_lines(out) == ['started', 'stopping']


def test_shutdown_emitted_once_when_it_cuts_timers_short(capsys):
    started = time.monotonic()
    assert run(LaunchDescription([
        RegisterEventHandler(OnShutdown(on_shutdown=[LogInfo(msg='shutdown seen')])),
        TimerAction(period=30.0, actions=[LogInfo(msg='too late')]),
        TimerAction(period=0.2, actions=[Shutdown(reason='enough')]),
    ])) == 0
    assert time.monotonic() - started < 10
    assert user_lines(capsys.readouterr().out) == ['shutdown seen']


def test_arguments_of_included_descriptions_and_choices():
    inner = LaunchDescription([
        DeclareLaunchArgument('world', default_value='empty', choices=['empty', 'maze'],
                              description='Which world'),
        DeclareLaunchArgument('robot', choices=['a', 'b']),
    ])
    outer = LaunchDescription([
        DeclareLaunchArgument('rate', default_value='10'),
        IncludeLaunchDescription(LaunchDescriptionSource(inner)),
    ])
    arguments = {argument.name: argument for argument in outer.get_launch_arguments()}
    assert list(arguments) == ['rate', 'world', 'robot']
    assert arguments['world'].description == "Which world. Valid choices are: ['empty', 'maze']"
    assert arguments['robot'].description == "One of: ['a', 'b']"
    with pytest.raises(RuntimeError, match='is not in provided choices'):
        DeclareLaunchArgument('bad', default_value='c', choices=['a', 'b'])


def test_process_output_goes_to_its_own_log_files(capsys, tmp_path):
    launch.logging.reset()
    launch.logging.launch_config.log_dir = str(tmp_path)
    try:
        script = 'import sys; print("to stdout"); print("to stderr", file=sys.stderr)'
        assert run(LaunchDescription([
            ExecuteProcess(cmd=[sys.executable, '-c', script], name='talky', output='own_log'),
        ])) == 0
    finally:
        launch.logging.reset()
    out = capsys.readouterr().out
    assert 'to stdout' not in out and 'to stderr' not in out
    logs = {path.name: path.read_text() for path in tmp_path.iterdir()}
    name = next(key[:-len('-stdout.log')] for key in logs if key.endswith('-stdout.log'))
    assert name.startswith('talky-')
    assert logs[f'{name}-stdout.log'] == f'[{name}] to stdout\n'
    assert logs[f'{name}-stderr.log'] == f'[{name}] to stderr\n'
    # both streams in one file too; their order between the two pipes is not fixed
    assert sorted(logs[f'{name}.log'].splitlines()) == [f'[{name}] to stderr',
                                                        f'[{name}] to stdout']
    assert 'process started with pid' in logs['launch.log']
