"""`ros2 interface` against the definition files of the ament index (no DDS needed)."""

import pytest

from ws_testing import ros2

SET_PEN = 'uint8 r\nuint8 g\nuint8 b\nuint8 width\nuint8 off\n---\n'
TWIST_NESTED = '\tfloat64 x\n\tfloat64 y\n\tfloat64 z\n'


@pytest.mark.parametrize('name, expected', [
    ('turtlesim/srv/SetPen', SET_PEN),
    ('example_interfaces/srv/AddTwoInts', 'int64 a\nint64 b\n---\nint64 sum\n'),
    ('turtlesim/msg/Pose',
     'float32 x\nfloat32 y\nfloat32 theta\n\nfloat32 linear_velocity\nfloat32 angular_velocity\n'),
    ('turtlesim/srv/Spawn', 'float32 x\nfloat32 y\nfloat32 theta\n'
     'string name # Optional.  A unique name will be created and returned if this is empty\n'
     '---\nstring name\n'),
    ('turtlesim/action/RotateAbsolute',
     '# The desired heading in radians\nfloat32 theta\n---\n'
     '# The angular displacement in radians to the starting position\nfloat32 delta\n---\n'
     '# The remaining rotation in radians\nfloat32 remaining\n'),
    ('std_srvs/srv/Empty', '---\n'),
    ('geometry_msgs/msg/Twist',
     '# This expresses velocity in free space broken into its linear and angular parts.\n\n'
     f'Vector3  linear\n{TWIST_NESTED}Vector3  angular\n{TWIST_NESTED}'),
])
def test_show_prints_the_definition(ros_env, name, expected):
    result = ros2(ros_env, 'interface', 'show', name)
    assert (result.stdout, result.stderr, result.returncode) == (expected, '', 0)


def test_show_no_comments_strips_comments_and_blank_lines(ros_env):
    result = ros2(ros_env, 'interface', 'show', '--no-comments', 'turtlesim/srv/Spawn')
    assert result.stdout == 'float32 x\nfloat32 y\nfloat32 theta\nstring name\n---\nstring name\n'
    twist = ros2(ros_env, 'interface', 'show', '--no-comments', 'geometry_msgs/msg/Twist')
    assert twist.stdout == f'Vector3  linear\n{TWIST_NESTED}Vector3  angular\n{TWIST_NESTED}'


def test_show_all_comments_keeps_nested_comments(ros_env):
    result = ros2(ros_env, 'interface', 'show', '--all-comments', 'geometry_msgs/msg/Twist')
    lines = result.stdout.splitlines()
    assert lines[2] == 'Vector3  linear'
    assert lines[3].startswith('\t# This represents a vector in free space.')
    assert '\tfloat64 x' in lines and lines.count('\tfloat64 z') == 2


def test_show_reads_the_name_from_stdin(ros_env):
    result = ros2(ros_env, 'interface', 'show', '-', stdin='turtlesim/srv/SetPen\n')
    assert (result.stdout, result.returncode) == (SET_PEN, 0)


@pytest.mark.parametrize('name, message', [
    ('turtlesim/SetPen', "Invalid name 'turtlesim/SetPen'. Expected three parts separated by '/'"),
    ('no_such_pkg/msg/X', "Unknown package 'no_such_pkg'"),
    # rosidl_runtime_py's message names the last file it tried: the .idl one.
    ('turtlesim/msg/Nope', "Could not find the interface '"),
])
def test_show_errors(ros_env, name, message):
    result = ros2(ros_env, 'interface', 'show', name)
    assert result.returncode == 1
    assert result.stdout == ''
    assert result.stderr.startswith(message)
    assert 'Traceback' not in result.stderr
    if message.startswith('Could not find'):
        assert result.stderr.endswith("/share/turtlesim/msg/Nope.idl'\n")


def test_proto_prints_quoted_yaml_of_a_default_instance(ros_env):
    result = ros2(ros_env, 'interface', 'proto', 'turtlesim/srv/Spawn')
    assert result.stdout == '"x: 0.0\ny: 0.0\ntheta: 0.0\nname: \'\'\n"\n'
    empty = ros2(ros_env, 'interface', 'proto', 'std_srvs/srv/Empty')
    assert empty.stdout == '"{}\n"\n'
    bare = ros2(ros_env, 'interface', 'proto', '--no-quotes', 'turtlesim/msg/Color')
    assert bare.stdout == 'r: 0\ng: 0\nb: 0\n\n'
    nested = ros2(ros_env, 'interface', 'proto', 'geometry_msgs/msg/Twist')
    assert nested.stdout == ('"linear:\n  x: 0.0\n  y: 0.0\n  z: 0.0\n'
                             'angular:\n  x: 0.0\n  y: 0.0\n  z: 0.0\n"\n')
    goal = ros2(ros_env, 'interface', 'proto', 'turtlesim/action/RotateAbsolute')
    assert goal.stdout == '"theta: 0.0\n"\n'


def test_list_has_three_sections_with_indented_sorted_entries(ros_env):
    result = ros2(ros_env, 'interface', 'list')
    lines = result.stdout.splitlines()
    messages, services, actions = (lines.index(h) for h in ('Messages:', 'Services:', 'Actions:'))
    assert messages == 0 < services < actions
    assert '    turtlesim/msg/Pose' in lines[messages:services]
    assert '    geometry_msgs/msg/Twist' in lines[messages:services]
    assert '    turtlesim/srv/SetPen' in lines[services:actions]
    assert '    std_srvs/srv/Empty' in lines[services:actions]
    assert '    example_interfaces/srv/AddTwoInts' in lines[services:actions]
    assert '    turtlesim/action/RotateAbsolute' in lines[actions:]
    entries = lines[messages + 1:services]
    assert entries == sorted(entries, key=lambda e: tuple(e.strip().split('/')))
    only = ros2(ros_env, 'interface', 'list', '-a')
    assert only.stdout.splitlines()[0] == 'Actions:'
    assert '    turtlesim/action/RotateAbsolute' in only.stdout.splitlines()


def test_packages_and_package(ros_env):
    packages = ros2(ros_env, 'interface', 'packages').stdout.splitlines()
    assert packages == sorted(packages)
    assert {'turtlesim', 'example_interfaces', 'geometry_msgs', 'std_srvs'} <= set(packages)
    turtlesim = ros2(ros_env, 'interface', 'package', 'turtlesim').stdout.splitlines()
    assert sorted(turtlesim) == [
        'turtlesim/action/RotateAbsolute', 'turtlesim/msg/Color', 'turtlesim/msg/Pose',
        'turtlesim/srv/Kill', 'turtlesim/srv/SetPen', 'turtlesim/srv/Spawn',
        'turtlesim/srv/TeleportAbsolute', 'turtlesim/srv/TeleportRelative']
    # -m/-s/-a: only those kinds, messages then services then actions, as upstream.
    kinds = ros2(ros_env, 'interface', 'package', '-a', '-m', 'turtlesim').stdout.splitlines()
    assert kinds == [n for n in turtlesim if '/msg/' in n] + ['turtlesim/action/RotateAbsolute']
    services = ros2(ros_env, 'interface', 'package', '--only-srvs', 'turtlesim')
    assert services.stdout.splitlines() == [n for n in turtlesim if '/srv/' in n]
    unknown = ros2(ros_env, 'interface', 'package', 'no_such_pkg')
    assert (unknown.returncode, unknown.stderr) == (1, "Unknown package 'no_such_pkg'\n")
