"""Every interface equals upstream Jazzy's, field for field, and installs its definition file."""

from pathlib import Path

import pytest
from ament_index_python.packages import get_package_share_directory

from support import interface_type

# Upstream turtlesim (1.8.2) definition files, byte for byte.
TURTLESIM_FILES = {
    'msg/Color.msg': 'uint8 r\nuint8 g\nuint8 b\n',
    'msg/Pose.msg': ('float32 x\nfloat32 y\nfloat32 theta\n\n'
                     'float32 linear_velocity\nfloat32 angular_velocity'),
    'srv/Kill.srv': 'string name\n---\n',
    'srv/SetPen.srv': 'uint8 r\nuint8 g\nuint8 b\nuint8 width\nuint8 off\n---\n',
    'srv/Spawn.srv': ('float32 x\nfloat32 y\nfloat32 theta\n'
                      'string name # Optional.  A unique name will be created and returned '
                      'if this is empty\n---\nstring name\n'),
    'srv/TeleportAbsolute.srv': 'float32 x\nfloat32 y\nfloat32 theta\n---\n',
    'srv/TeleportRelative.srv': 'float32 linear\nfloat32 angular\n---\n',
    'action/RotateAbsolute.action': (
        '# The desired heading in radians\nfloat32 theta\n---\n'
        '# The angular displacement in radians to the starting position\nfloat32 delta\n---\n'
        '# The remaining rotation in radians\nfloat32 remaining\n'),
}

# (type, part) -> ordered fields as rosidl names their types.
F32 = 'float'
EXPECTED_FIELDS = {
    ('turtlesim/msg/Color', None): {'r': 'uint8', 'g': 'uint8', 'b': 'uint8'},
    ('turtlesim/msg/Pose', None): {'x': F32, 'y': F32, 'theta': F32,
                                   'linear_velocity': F32, 'angular_velocity': F32},
    ('turtlesim/srv/Kill', 'Request'): {'name': 'string'},
    ('turtlesim/srv/Kill', 'Response'): {},
    ('turtlesim/srv/SetPen', 'Request'): {'r': 'uint8', 'g': 'uint8', 'b': 'uint8',
                                          'width': 'uint8', 'off': 'uint8'},
    ('turtlesim/srv/SetPen', 'Response'): {},
    ('turtlesim/srv/Spawn', 'Request'): {'x': F32, 'y': F32, 'theta': F32, 'name': 'string'},
    ('turtlesim/srv/Spawn', 'Response'): {'name': 'string'},
    ('turtlesim/srv/TeleportAbsolute', 'Request'): {'x': F32, 'y': F32, 'theta': F32},
    ('turtlesim/srv/TeleportAbsolute', 'Response'): {},
    ('turtlesim/srv/TeleportRelative', 'Request'): {'linear': F32, 'angular': F32},
    ('turtlesim/srv/TeleportRelative', 'Response'): {},
    ('turtlesim/action/RotateAbsolute', 'Goal'): {'theta': F32},
    ('turtlesim/action/RotateAbsolute', 'Result'): {'delta': F32},
    ('turtlesim/action/RotateAbsolute', 'Feedback'): {'remaining': F32},
    ('example_interfaces/srv/AddTwoInts', 'Request'): {'a': 'int64', 'b': 'int64'},
    ('example_interfaces/srv/AddTwoInts', 'Response'): {'sum': 'int64'},
    ('example_interfaces/srv/SetBool', 'Request'): {'data': 'boolean'},
    ('example_interfaces/srv/SetBool', 'Response'): {'success': 'boolean', 'message': 'string'},
    ('example_interfaces/srv/Trigger', 'Request'): {},
    ('example_interfaces/srv/Trigger', 'Response'): {'success': 'boolean', 'message': 'string'},
    ('example_interfaces/action/Fibonacci', 'Goal'): {'order': 'int32'},
    ('example_interfaces/action/Fibonacci', 'Result'): {'sequence': 'sequence<int32>'},
    ('example_interfaces/action/Fibonacci', 'Feedback'): {'sequence': 'sequence<int32>'},
    ('example_interfaces/msg/Empty', None): {},
    ('example_interfaces/msg/MultiArrayDimension', None): {
        'label': 'string', 'size': 'uint32', 'stride': 'uint32'},
    ('example_interfaces/msg/MultiArrayLayout', None): {
        'dim': 'sequence<example_interfaces/MultiArrayDimension>', 'data_offset': 'uint32'},
}
# The primitive wrappers: example_interfaces/msg/<Name> holds one field `data`.
PRIMITIVES = {
    'Bool': 'boolean', 'Byte': 'octet', 'Char': 'uint8', 'Float32': 'float', 'Float64': 'double',
    'Int8': 'int8', 'Int16': 'int16', 'Int32': 'int32', 'Int64': 'int64', 'UInt8': 'uint8',
    'UInt16': 'uint16', 'UInt32': 'uint32', 'UInt64': 'uint64', 'String': 'string',
    'WString': 'wstring',
}
for _name, _type in PRIMITIVES.items():
    EXPECTED_FIELDS[(f'example_interfaces/msg/{_name}', None)] = {'data': _type}
    if _name not in ('Bool', 'Char', 'String', 'WString'):
        EXPECTED_FIELDS[(f'example_interfaces/msg/{_name}MultiArray', None)] = {
            'layout': 'example_interfaces/MultiArrayLayout', 'data': f'sequence<{_type}>'}


@pytest.mark.parametrize('relative, text', TURTLESIM_FILES.items())
def test_turtlesim_definition_files_are_installed_verbatim(relative, text):
    installed = Path(get_package_share_directory('turtlesim')) / relative
    assert installed.read_text() == text


@pytest.mark.parametrize('name, part', EXPECTED_FIELDS.keys(),
                         ids=[f'{n}{"." + p if p else ""}' for n, p in EXPECTED_FIELDS])
def test_generated_fields_equal_upstream(name, part):
    interface = interface_type(name)
    cls = getattr(interface, part) if part else interface
    # get_fields_and_field_types() keeps the definition's order, which the wire format follows.
    expected = EXPECTED_FIELDS[(name, part)]
    assert list(cls.get_fields_and_field_types().items()) == list(expected.items())


def test_example_interfaces_set_is_complete():
    share = Path(get_package_share_directory('example_interfaces'))
    installed = {f'example_interfaces/{p.parent.name}/{p.stem}'
                 for kind in ('msg', 'srv', 'action') for p in (share / kind).glob(f'*.{kind}')}
    expected = {name for name, _ in EXPECTED_FIELDS if name.startswith('example_interfaces/')}
    assert installed == expected
    assert len([n for n in installed if '/msg/' in n]) == 29
