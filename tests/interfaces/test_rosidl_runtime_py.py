"""rosidl_runtime_py with upstream's API, on the wheels' generated messages: messages to
ordered dicts, YAML and CSV (with truncate_length, no_arr, no_str), set_message_fields with
upstream's exception types and return value (the Header 'auto' / Time 'now' setters) and
our one-line errors naming the field, interfaces by name and by package.
In-process, no DDS: these are pure functions of generated message classes.
"""
from __future__ import annotations

import array
import re
import subprocess
import sys
from collections import OrderedDict

import numpy
import pytest
from builtin_interfaces.msg import Time
from geometry_msgs.msg import PoseWithCovariance, Twist
from rosidl_parser.definition import NamespacedType, UnboundedSequence
from rosidl_runtime_py.set_message import FieldError
from sensor_msgs.msg import Image, JointState
from std_msgs.msg import Header, String
from tf2_msgs.action import LookupTransform
from turtlesim.srv import SetPen

from rosidl_runtime_py import (
    get_interface_path,
    get_interfaces,
    get_message_interfaces,
    get_service_interfaces,
    import_message_from_namespaced_type,
    message_to_csv,
    message_to_ordereddict,
    message_to_yaml,
    set_message_fields,
    utilities,
)


def joint_state() -> JointState:
    return JointState(header=Header(stamp=Time(sec=3, nanosec=4), frame_id='base'),
                      name=['elbow', 'wrist'], position=[0.5, -1.25], velocity=[], effort=[])


def test_message_to_ordereddict_yaml_and_csv() -> None:
    state = joint_state()
    plain = message_to_ordereddict(state)
    assert isinstance(plain, OrderedDict) and isinstance(plain['header'], OrderedDict)
    assert list(plain) == ['header', 'name', 'position', 'velocity', 'effort']
    assert plain['position'] == [0.5, -1.25]  # an array.array in the message, a list here
    assert message_to_yaml(state) == (
        'header:\n  stamp:\n    sec: 3\n    nanosec: 4\n  frame_id: base\n'
        'name:\n- elbow\n- wrist\nposition:\n- 0.5\n- -1.25\nvelocity: []\neffort: []\n')
    # Flow style flows the sequences only; mappings stay in block style (ros2 topic echo -f).
    assert message_to_yaml(state, flow_style=True).startswith(
        'header:\n  stamp:\n    sec: 3\n    nanosec: 4\n  frame_id: base\n'
        'name: [elbow, wrist]\nposition: [0.5, -1.25]\n')
    assert message_to_csv(state) == '3,4,base,elbow,wrist,0.5,-1.25,,'


def test_truncation_and_the_no_arr_no_str_summaries() -> None:
    image = Image(height=1, width=300, encoding='rgb8', data=list(range(256)) * 3)
    short = message_to_ordereddict(image, truncate_length=3)
    assert short['data'] == [0, 1, 2, '...'] and short['encoding'] == 'rgb...'
    assert message_to_csv(image, truncate_length=2).endswith(',rg...,0,0,0,1,...')
    summary = message_to_ordereddict(image, no_arr=True, no_str=True)
    assert summary['data'] == '<sequence type: uint8, length: 768>'
    assert summary['encoding'] == '<string length: <4>>'
    covariance = message_to_ordereddict(PoseWithCovariance(), no_arr=True)
    assert covariance['covariance'] == '<array type: double[36]>'
    assert message_to_yaml(String(data='héllo')) == 'data: héllo\n'


def test_set_message_fields_sets_nested_values_and_returns_stamp_setters() -> None:
    state = JointState()
    assert set_message_fields(state, {'name': ['a'], 'position': numpy.array([1, 2]),
                                      'velocity': array.array('d', [3.0]),
                                      'header': {'frame_id': 'odom'}}) == []
    assert list(state.position) == [1.0, 2.0] and list(state.velocity) == [3.0]
    assert state.header.frame_id == 'odom'
    # A message instance is taken as it is (upstream's nested-message case).
    pose = PoseWithCovariance()
    set_message_fields(pose, {'pose': {'position': {'x': 1}}, 'covariance': [0.5] * 36})
    assert pose.pose.position.x == 1.0 and pose.covariance[35] == 0.5
    # Header 'auto' and Time 'now' only when expanded; each gives a setter taking a Time.
    state = JointState(header=Header(frame_id='keep'))
    setters = set_message_fields(state, {'header': 'auto'}, expand_header_auto=True)
    assert len(setters) == 1
    setters[0](Time(sec=7, nanosec=8))
    assert (state.header.stamp.sec, state.header.stamp.nanosec) == (7, 8)
    assert state.header.frame_id == 'keep'
    setters = set_message_fields(state, {'header': {'stamp': 'now', 'frame_id': 'x'}},
                                 expand_time_now=True)
    setters[0](Time(sec=9))
    assert (state.header.stamp.sec, state.header.frame_id) == (9, 'x')


@pytest.mark.parametrize('message, values, error, explanation', [
    (Twist(), {'angular': {'w': 1.0}}, AttributeError,
     "'angular.w' is not a field of geometry_msgs/msg/Vector3 (fields: x, y, z)"),
    (Twist(), {'linear': {'x': 'fast'}}, ValueError, "'linear.x' must be a number, got 'fast'"),
    (SetPen.Request(), {'r': 256}, ValueError, "'r' must be an integer in [0, 255], got 256"),
    (SetPen.Request(), {'width': True}, ValueError,
     "'width' must be an integer in [0, 255], got True"),
    (String(), {'data': 5}, ValueError,
     "'data' must be a string, got 5 (quote it, e.g. '\"123\"')"),
    (PoseWithCovariance(), {'covariance': [0.0]}, ValueError,
     "'covariance' must have exactly 36 elements, got 1"),
    (JointState(), {'header': 'auto'}, TypeError,
     "'header' expects a mapping of field names to values, got 'auto'"),
])
def test_bad_values_raise_upstreams_types_with_one_line_naming_the_field(
        message, values, error, explanation) -> None:
    with pytest.raises(error) as raised:
        set_message_fields(message, values)
    assert isinstance(raised.value, FieldError)
    assert raised.value.explanation == explanation


def test_a_non_mapping_reads_as_upstreams_type_error() -> None:
    with pytest.raises(TypeError, match=r"^Value 'now' is expected to be a dictionary but is a "
                       r'str$'):
        set_message_fields(JointState(), {'header': {'stamp': 'now'}})
    with pytest.raises(TypeError):
        set_message_fields(Twist(), 'not a dict')


def test_interfaces_by_name() -> None:
    assert utilities.get_message('std_msgs/msg/String') is String
    assert utilities.get_message('std_msgs/String') is String
    assert utilities.get_service('turtlesim/SetPen') is SetPen
    assert utilities.get_action('tf2_msgs/action/LookupTransform') is LookupTransform
    assert utilities.get_interface('turtlesim/srv/SetPen') is SetPen
    with pytest.raises(ValueError, match="Expected the full name of a service, got "
                       "'std_msgs/msg/String'"):
        utilities.get_service('std_msgs/msg/String')
    with pytest.raises(ModuleNotFoundError):
        utilities.get_message('no_such_pkg/msg/Nothing')
    for bad in ('../../etc/passwd', 'std_msgs/msg/', 'std msgs/msg/String'):
        with pytest.raises(ValueError, match=re.escape(
                'is not an interface type: expected <package>/<msg|srv|action>/<Name>')):
            utilities.get_interface(bad)
    feedback = NamespacedType(['tf2_msgs', 'action'], 'LookupTransform_FeedbackMessage')
    assert import_message_from_namespaced_type(feedback) is \
        LookupTransform.Impl.FeedbackMessage
    with pytest.warns(DeprecationWarning):
        assert import_message_from_namespaced_type(
            UnboundedSequence(NamespacedType(['std_msgs', 'msg'], 'String'))) is String


def test_interfaces_by_package() -> None:
    assert 'msg/String' in get_interfaces(['std_msgs'])['std_msgs']
    messages = get_message_interfaces(['turtlesim', 'std_srvs'])
    assert sorted(messages) == ['turtlesim'] and 'msg/Pose' in messages['turtlesim']
    assert sorted(get_service_interfaces(['turtlesim'])['turtlesim']) == [
        'srv/Kill', 'srv/SetPen', 'srv/Spawn', 'srv/TeleportAbsolute', 'srv/TeleportRelative']
    with pytest.raises(LookupError, match="Unknown package 'no_such_package'"):
        get_interfaces(['no_such_package'])
    assert get_interface_path('turtlesim/msg/Pose').endswith('share/turtlesim/msg/Pose.msg')
    assert get_interface_path('std_msgs/msg/String.idl').endswith('String.idl')
    with pytest.raises(ValueError, match=r"Must not contain '\.\.'"):
        get_interface_path('std_msgs/../String')


def test_looking_interfaces_up_imports_neither_numpy_nor_yaml() -> None:
    # `ros2` verbs look types up through rosidl_runtime_py.utilities: they start without
    # paying for numpy and yaml, which conversion imports when it first needs them.
    probe = ('import sys; from rosidl_runtime_py.utilities import get_message; '
             "get_message('std_msgs/msg/String'); "
             "print(sorted(m for m in ('numpy', 'yaml') if m in sys.modules))")
    ran = subprocess.run([sys.executable, '-c', probe], capture_output=True, text=True,
                         timeout=60)
    assert ran.stdout == '[]\n', ran.stdout + ran.stderr
