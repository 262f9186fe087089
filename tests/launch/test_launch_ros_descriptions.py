"""launch_ros's descriptions and utilities as a launch file uses them, without running it:
typed parameter values, Node's `parameters` list read as upstream reads it, namespaces, and
the command line Node builds from SetParameter / SetParametersFromFile / SetRemap /
PushROSNamespace (the nodes themselves run in test_launch_ros.py); ROSTimer on sim time,
SetROSLogDir and a component container in a real launch."""

from __future__ import annotations

import sys
import time
from pathlib import Path

import pytest
import yaml
from builtin_interfaces.msg import Time
from launch.actions import (
    ExecuteProcess,
    OpaqueFunction,
    PopLaunchConfigurations,
    PushLaunchConfigurations,
)
from launch.substitutions import EnvironmentVariable, TextSubstitution
from launch_ros.actions import (
    ComposableNodeContainer,
    Node,
    PushROSNamespace,
    ROSTimer,
    SetParameter,
    SetParametersFromFile,
    SetRemap,
    SetROSLogDir,
    SetUseSimTime,
)
from launch_ros.actions.load_composable_nodes import get_composable_node_load_request
from launch_ros.descriptions import ComposableNode, Parameter, ParameterFile, ParameterValue
from launch_ros.substitutions import Parameter as ParameterSubstitution
from launch_ros.utilities import (
    evaluate_parameters,
    make_namespace_absolute,
    normalize_parameters,
    prefix_namespace,
)
from rosgraph_msgs.msg import Clock

from launch import LaunchContext, LaunchDescription, LaunchService
from support import Background


def text(value: str) -> TextSubstitution:
    return TextSubstitution(text=value)


def evaluated(parameters: list) -> tuple:
    return evaluate_parameters(LaunchContext(), normalize_parameters(parameters))


def test_parameter_value_types_its_substitutions():
    context = LaunchContext()
    # A xacro-like output stays text with value_type=str (YAML would read it as a dict).
    assert ParameterValue(text('{robot: r2d2}'), value_type=str).evaluate(context) == \
        '{robot: r2d2}'
    assert ParameterValue(['[', text('1, '), text('2'), ']'],
                          value_type=list[int]).evaluate(context) == [1, 2]
    value = ParameterValue(text('7'))
    assert isinstance(value.value, list)  # substitutions until evaluated
    assert value.evaluate(context) == 7 and value.value == 7
    assert ParameterValue('plain').value == 'plain'
    with pytest.raises(TypeError):
        ParameterValue('1', value_type=int)  # given text, not an int
    with pytest.raises(ValueError):
        ParameterValue(text('[1, two, 3]')).evaluate(context)  # not one type
    assert Parameter(name=['rate', text('_hz')], value=text('2.5')).evaluate(context) == \
        ('rate_hz', 2.5)


def test_parameter_dicts_are_flattened_and_typed_as_upstream():
    assert evaluated([{'group': {'int': 1, 'mixed': [2, 3.5], 'texts': ['True', '1'],
                                 'flag': text('off')}}]) == (
        {'group.int': 1, 'group.mixed': (2.0, 3.5), 'group.texts': ('True', '1'),
         'group.flag': False},)
    assert evaluated([{'joined': [text('fiz'), 'buz'], 'items': [[text('fiz')], 'buz']}]) == (
        {'joined': 'fizbuz', 'items': ('fiz', 'buz')},)
    assert evaluated(['/no/such.yaml']) == (Path('/no/such.yaml'),)
    with pytest.raises(TypeError, match='Allowed value types'):
        evaluated([{'nested': text('{a: 1}')}])
    with pytest.raises(TypeError, match='Expected a non-empty sequence'):
        evaluated([{'dissimilar': [True, 2.0, 3]}])
    with pytest.raises(TypeError, match='Unable to parse'):
        evaluated([{'broken': text('a : b : c')}])
    for bad in ({'a': 1}, [{5: 'five'}], [{'nested': [1, [2, 3]]}], [{'a_set': {1, 2}}]):
        with pytest.raises(TypeError):
            normalize_parameters(bad)


def test_namespaces_combine_as_upstream():
    assert prefix_namespace('/robot', 'arm/') == '/robot/arm'
    assert prefix_namespace('/', 'arm') == '/arm'
    assert prefix_namespace('robot', '/abs') == '/abs'
    assert prefix_namespace('', 'arm') == 'arm'
    assert prefix_namespace('robot', None) == 'robot'
    assert prefix_namespace(None, None) is None
    assert make_namespace_absolute('') == '/'


def command_of(node: Node, context: LaunchContext) -> list[str]:
    """The node's command words that are plain text (not its name/namespace locals)."""
    return [context.perform_substitution(part[0]) for part in node.cmd
            if isinstance(part[0], TextSubstitution)]


def test_node_command_carries_the_scoped_ros_settings(tmp_path):
    params = tmp_path / 'params.yaml'
    params.write_text('/**:\n  ros__parameters:\n    speed: 3\n')
    context = LaunchContext()
    PushLaunchConfigurations().visit(context)
    for action in (PushROSNamespace('robot'), SetParameter('use_sim_time', True),
                   SetParametersFromFile(str(params)), SetRemap('cmd_vel', 'cmd')):
        action.visit(context)
    node = Node(package='turtlesim', executable='turtlesim_node', name='sim', namespace='arm',
                parameters=[{'background_r': 10}], remappings=[('pose', 'where')])
    node._perform_substitutions(context)
    assert node.node_name == '/robot/arm/sim' and node.expanded_node_namespace == '/robot/arm'
    words = command_of(node, context)
    assert words[:5] == ['--ros-args', '-r', '-r', '-p', 'use_sim_time:=True']
    assert words[5:7] == ['--params-file', str(params)]
    assert words[7] == '--params-file'
    assert yaml.safe_load(Path(words[8]).read_text()) == {
        '/robot/arm/sim': {'ros__parameters': {'background_r': 10}}}
    assert words[9:] == ['-r', 'cmd_vel:=cmd', '-r', 'pose:=where']
    assert node.expanded_remapping_rules == [('cmd_vel', 'cmd'), ('pose', 'where')]
    assert ParameterSubstitution('use_sim_time').perform(context) == 'True'
    PopLaunchConfigurations().visit(context)
    assert context.launch_configurations == {}  # all of it was scoped


def test_node_parameter_descriptions_become_p_arguments(monkeypatch):
    monkeypatch.setenv('LRT_VALUE', '0.5')
    node = Node(executable='talker', parameters=[
        Parameter('gain', EnvironmentVariable('LRT_VALUE'), value_type=float),
        Parameter('names', ['a', 'b'])])
    context = LaunchContext()
    node._perform_substitutions(context)
    words = command_of(node, context)
    assert node.node_name == '<node_namespace_unspecified>/<node_name_unspecified>'
    assert not node.is_node_name_fully_specified()
    assert [yaml.safe_load(w.split(':=', 1)[1]) for w in words if ':=' in w] == [0.5, ['a', 'b']]


def test_parameter_file_substitutions_are_performed_into_a_copy(tmp_path, monkeypatch):
    monkeypatch.setenv('LRT_NODE', 'talker')
    source = tmp_path / 'params.yaml'
    source.write_text('/$(env LRT_NODE):\n  ros__parameters:\n    rate: $(env LRT_RATE 2)\n')
    description = ParameterFile(str(source), allow_substs=True)
    copy = description.evaluate(LaunchContext())
    assert copy != source and yaml.safe_load(copy.read_text()) == {
        '/talker': {'ros__parameters': {'rate': 2}}}
    description.cleanup()
    assert not copy.exists()
    kept = ParameterFile(source)
    assert kept.evaluate(LaunchContext()) == source


def test_composable_node_load_request_as_upstream_builds_it(tmp_path):
    params = tmp_path / 'params.yaml'
    params.write_text('/**:\n  ros__parameters:\n    every: 1\n'
                      '/robot/cam:\n  ros__parameters:\n    mine: 2\n'
                      '/robot/other:\n  ros__parameters:\n    not_mine: 3\n')
    context = LaunchContext()
    for action in (PushROSNamespace('robot'), SetRemap('image', 'raw'),
                   SetParametersFromFile(str(params)), SetParameter('fps', 30)):
        action.visit(context)
    request = get_composable_node_load_request(ComposableNode(
        package='image_proc', plugin='image_proc::RectifyNode', name='cam',
        parameters=[{'width': 640}], remappings=[('info', 'camera_info')]), context)
    assert (request.package_name, request.plugin_name, request.node_name,
            request.node_namespace) == ('image_proc', 'image_proc::RectifyNode', 'cam', '/robot')
    assert list(request.remap_rules) == ['image:=raw', 'info:=camera_info']
    assert [(p.name, p.value.integer_value) for p in request.parameters] == [
        ('every', 1), ('mine', 2), ('fps', 30), ('width', 640)]


def run_launch(actions: list) -> tuple[int, LaunchService]:
    service = LaunchService()
    service.include_launch_description(LaunchDescription(actions))
    return service.run(), service


@pytest.mark.parametrize('sim_time_first', [True, False])
def test_ros_timer_follows_the_ros_clock_of_the_launch(probe, domain, monkeypatch,
                                                      sim_time_first):
    # With SetUseSimTime the launch's own node follows /clock: a 100 s timer fires at 100 s
    # of sim time, which the probe publishes 20 s at a time every 0.1 s. Listed before
    # SetUseSimTime, the timer still counts from sim time 0 (upstream makes it in a task),
    # not from the first /clock message.
    from launch_ros.ros_adapters import get_ros_node
    monkeypatch.setenv('ROS_DOMAIN_ID', str(domain))
    clock = probe.node.create_publisher(Clock, '/clock', 10)
    now = [0]

    def tick() -> None:
        now[0] += 20
        clock.publish(Clock(clock=Time(sec=now[0])))

    probe.node.create_timer(0.1, tick)
    fired: list[tuple[float, int]] = []
    started = time.monotonic()
    timer = ROSTimer(period=100.0, actions=[OpaqueFunction(function=lambda context: fired.append(
        (time.monotonic(), get_ros_node(context).get_clock().now().nanoseconds)))])
    actions = [SetUseSimTime(True), timer] if sim_time_first else [timer, SetUseSimTime(True)]
    with Background(probe):
        code, _ = run_launch(actions)
    assert code == 0 and len(fired) == 1
    assert fired[0][0] - started < 10  # not 100 s of wall time
    assert fired[0][1] == 100 * 10**9


def test_set_ros_log_dir_sets_where_later_nodes_log(tmp_path, monkeypatch):
    monkeypatch.setenv('ROS_LOG_DIR', str(tmp_path))
    seen = tmp_path / 'seen.txt'
    code, _ = run_launch([
        SetROSLogDir('inner'),
        ExecuteProcess(cmd=[sys.executable, '-c', 'import os, sys; open(sys.argv[1], "w")'
                            '.write(os.environ["ROS_LOG_DIR"])', str(seen)]),
    ])
    assert code == 0 and seen.read_text() == str(tmp_path / 'inner')


def test_a_component_container_fails_with_one_clear_line():
    code, _ = run_launch([ComposableNodeContainer(
        name='container', namespace='', package='rclcpp_components',
        executable='component_container',
        composable_node_descriptions=[ComposableNode(package='p', plugin='p::Node')])])
    assert code == 1


def test_frontend_node_params_are_typed_and_unescaped_as_upstream():
    """<param value-sep> items lose their escapes (`\\'2\\'` is the text '2' in quotes),
    are read as YAML unless a type says otherwise; nested <param>s make dotted names."""
    import io

    from launch.frontend import Parser
    xml = r'''<launch><node pkg="demo_nodes_py" exec="talker" name="t">
      <param name="quoted" value="\'2\', \'5\'" value-sep=", "/>
      <param name="numbers" value="1, 2" value-sep=", "/>
      <param name="text" type="str" value="a: b"/>
      <param name="group"><param name="flag" value="true"/></param>
    </node></launch>'''
    root, parser = Parser.load(io.StringIO(xml))
    node = parser.parse_description(root).entities[0]
    context = LaunchContext()
    node._perform_substitutions(context)
    words = command_of(node, context)
    values: dict = {}
    for i in [i for i, word in enumerate(words) if word == '--params-file']:
        values.update(yaml.safe_load(Path(words[i + 1]).read_text())['/**']['ros__parameters'])
    assert values == {'quoted': ["'2'", "'5'"], 'numbers': [1, 2], 'text': 'a: b',
                      'group.flag': True}
