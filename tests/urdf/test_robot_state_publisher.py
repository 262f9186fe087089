"""robot_state_publisher as a process over DDS: bad descriptions (one line naming the element,
the node stays up and takes a later good one), its parameters as upstream defines them
(frame_prefix, publish_frequency, ignore_timestamp) and each joint type on /tf or /tf_static."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest
from rclpy.parameter import Parameter

from support import TestNode, ros2

NODE = 'robot_state_publisher'
LOG = r'^\[{level}\] \[\d+\.\d+\] \[robot_state_publisher\]: '
ALLOWED = 'revolute, continuous, prismatic, fixed, floating, planar'

BOGUS_TYPE = '''<robot name="r"><link name="a"/><link name="b"/>
  <joint name="x" type="bogus"><parent link="a"/><child link="b"/></joint></robot>'''
# A kinematic loop: link c has two parents (a tree has one).
TWO_PARENTS = '''<robot name="r"><link name="a"/><link name="b"/><link name="c"/>
  <joint name="a_to_b" type="fixed"><parent link="a"/><child link="b"/></joint>
  <joint name="a_to_c" type="fixed"><parent link="a"/><child link="c"/></joint>
  <joint name="b_to_c" type="fixed"><parent link="b"/><child link="c"/></joint></robot>'''
MALFORMED = '<robot name="r"><link name="a"></robot>'
MISSING_MESH = '''<robot name="r"><link name="base_link"><visual><geometry>
  <mesh filename="package://urdf_tutorial/meshes/no_such.stl"/></geometry></visual></link>
  </robot>'''
# One line: `ros2 param set` reads the value as YAML, which folds line breaks into spaces.
GOOD = ('<robot name="good"><link name="base_link"/><link name="camera"/>'
        '<joint name="camera_joint" type="fixed"><parent link="base_link"/>'
        '<child link="camera"/><origin xyz="0.1 0 0.3"/></joint></robot>')

# One joint of each type under `base`.
JOINTS = '''<robot name="joints">
  <link name="base"/><link name="arm"/><link name="wheel"/><link name="slider"/>
  <link name="camera"/><link name="table"/><link name="drone"/>
  <joint name="revolute_joint" type="revolute"><parent link="base"/><child link="arm"/>
    <origin xyz="0 0 0.5"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
  <joint name="continuous_joint" type="continuous"><parent link="arm"/><child link="wheel"/>
    <origin xyz="0.2 0 0"/><axis xyz="0 1 0"/></joint>
  <joint name="prismatic_joint" type="prismatic"><parent link="base"/><child link="slider"/>
    <origin xyz="0 0 0.1"/><axis xyz="1 0 0"/>
    <limit lower="0" upper="1" effort="1" velocity="1"/></joint>
  <joint name="fixed_joint" type="fixed"><parent link="base"/><child link="camera"/>
    <origin xyz="0.1 0 0.3" rpy="0 0 1.5707963267948966"/></joint>
  <joint name="planar_joint" type="planar"><parent link="base"/><child link="table"/>
    <origin xyz="1 0 0"/></joint>
  <joint name="floating_joint" type="floating"><parent link="base"/><child link="drone"/>
    <origin xyz="0 0 2"/></joint>
</robot>'''


def params_file(path: Path, **parameters: object) -> str:
    """A --params-file for the node (JSON is YAML: the XML stays one quoted string)."""
    path.write_text(json.dumps({NODE: {'ros__parameters': parameters}}))
    return str(path)


def set_parameter(probe: TestNode, name: str, value: object):
    from rcl_interfaces.srv import SetParameters
    request = SetParameters.Request(parameters=[Parameter(name, value=value).to_parameter_msg()])
    return probe.call(SetParameters, f'/{NODE}/set_parameters', request).results[0]


def latched(probe: TestNode, msg_type, topic: str) -> list:
    from rclpy.qos import DurabilityPolicy, QoSProfile
    return probe.collect(msg_type, topic,
                         QoSProfile(depth=10, durability=DurabilityPolicy.TRANSIENT_LOCAL))


def test_bad_descriptions_are_one_line_and_the_node_takes_a_good_one(
        launch, probe, ros_env, tmp_path: Path) -> None:
    from std_msgs.msg import String
    from tf2_msgs.msg import TFMessage
    node = launch(NODE, NODE, '--ros-args', '--params-file',
                  params_file(tmp_path / 'bogus.yaml', robot_description=BOGUS_TYPE))
    # Unknown joint type at start-up: urdfdom's words, the allowed types, the node stays up.
    node.wait_for_output(LOG.format(level='ERROR') + re.escape(
        f'Joint [x] has no known type [bogus] (allowed: {ALLOWED}); waiting for a valid '
        'robot_description') + '$', timeout=30)
    descriptions = latched(probe, String, '/robot_description')
    statics = latched(probe, TFMessage, '/tf_static')

    # Refused parameter values: the reason names the element, one WARN line each.
    for xml, reason in (
            (TWO_PARENTS, "joint 'b_to_c': child link [c] already has a parent "
                          "(joint 'a_to_c')"),
            (MALFORMED, 'robot description is not valid XML: Opening and ending tag '
                        'mismatch: link line 1 and robot, line 1, column 40'),
            (BOGUS_TYPE, f'Joint [x] has no known type [bogus] (allowed: {ALLOWED})'),
            ('', 'Empty URDF is not allowed')):
        result = set_parameter(probe, 'robot_description', xml)
        assert (result.successful, result.reason) == (False, reason)
        if xml:
            node.wait_for_output(LOG.format(level='WARN') + re.escape(reason) + '$')
    assert node.popen.poll() is None, node.output

    # A missing mesh: upstream does not look at meshes; we use the model and warn once.
    assert set_parameter(probe, 'robot_description', MISSING_MESH).successful
    node.wait_for_output(LOG.format(level='WARN') + re.escape(
        "link 'base_link': mesh [package://urdf_tutorial/meshes/no_such.stl] not found: no file ")
        + r'\S+/share/urdf_tutorial/meshes/no_such\.stl$')
    probe.spin_until(lambda: descriptions and descriptions[-1].data == MISSING_MESH, 15,
                     'the mesh model on /robot_description')

    # `ros2 param set` of a good description: published and its fixed joint latched.
    done = ros2(ros_env, 'param', 'set', f'/{NODE}', 'robot_description', GOOD)
    assert (done.returncode, done.stdout) == (0, 'Set parameter successful\n'), done.stderr
    probe.spin_until(lambda: descriptions and descriptions[-1].data == GOOD, 15,
                     'the good model on /robot_description')
    probe.spin_until(lambda: any(t.child_frame_id == 'camera' for m in statics
                                 for t in m.transforms), 15, 'base_link -> camera on /tf_static')
    camera = next(t for m in statics for t in m.transforms if t.child_frame_id == 'camera')
    assert camera.header.frame_id == 'base_link'
    assert (camera.transform.translation.x, camera.transform.translation.z) == \
        pytest.approx((0.1, 0.3))
    assert node.popen.poll() is None
    assert 'Traceback' not in node.output


def test_joint_types_frame_prefix_publish_frequency_ignore_timestamp(
        launch, probe, tmp_path: Path) -> None:
    from builtin_interfaces.msg import Time as TimeMsg
    from rclpy.qos import qos_profile_sensor_data
    from sensor_msgs.msg import JointState
    from std_msgs.msg import Header
    from tf2_msgs.msg import TFMessage
    node = launch(NODE, NODE, '--ros-args', '--params-file', params_file(
        tmp_path / 'joints.yaml', robot_description=JOINTS, frame_prefix='robot1/',
        publish_frequency=2.0))
    node.wait_for_output(LOG.format(level='INFO') + 'Robot initialized$', timeout=30)
    # kdl_parser's warning, for planar and floating joints alike.
    for joint in ('planar_joint', 'floating_joint'):
        assert re.search(LOG.format(level='WARN') + re.escape(
            f"Converting unknown joint type of joint '{joint}' into a fixed joint") + '$',
            node.output, re.MULTILINE), node.output
    statics = latched(probe, TFMessage, '/tf_static')
    moving = probe.collect(TFMessage, '/tf')

    # Fixed and planar joints latched on /tf_static, prefixed; the floating one nowhere.
    def static_pairs() -> set[tuple[str, str]]:
        return {(t.header.frame_id, t.child_frame_id) for m in statics for t in m.transforms}
    probe.spin_until(lambda: len(static_pairs()) >= 2, 15, 'the fixed joints on /tf_static')
    assert static_pairs() == {('robot1/base', 'robot1/camera'), ('robot1/base', 'robot1/table')}
    camera = next(t.transform for m in statics for t in m.transforms
                  if t.child_frame_id == 'robot1/camera')
    assert (camera.translation.x, camera.translation.y, camera.translation.z) == \
        pytest.approx((0.1, 0.0, 0.3))
    assert (camera.rotation.z, camera.rotation.w) == pytest.approx(
        (math.sin(math.pi / 4), math.cos(math.pi / 4)))

    states = probe.node.create_publisher(JointState, '/joint_states', qos_profile_sensor_data)
    base_ns = probe.node.get_clock().now().nanoseconds // 10**9 * 10**9

    def stamp(offset: float) -> TimeMsg:
        ns = base_ns + round(offset * 1e9)
        return TimeMsg(sec=ns // 10**9, nanosec=ns % 10**9)

    def send(offset: float, position: float) -> None:
        states.publish(JointState(
            header=Header(stamp=stamp(offset)),
            name=['revolute_joint', 'continuous_joint', 'prismatic_joint', 'floating_joint'],
            position=[position, 2 * position, position / 2, 0.7]))

    def stamps_seen() -> list[float]:
        seen = []
        for m in moving:
            offset = round((m.transforms[0].header.stamp.sec * 10**9
                            + m.transforms[0].header.stamp.nanosec - base_ns) / 1e9, 3)
            if offset not in seen:
                seen.append(offset)
        return seen

    def seen(offset: float) -> bool:
        probe.spin_for(0.1)
        return offset in stamps_seen()

    # Until both ends have matched: the same stamp again is throttled, so it is sent once
    # to the node's /joint_states however often it is repeated here.
    def first_seen() -> bool:
        send(0.0, 0.5)
        return seen(0.0)
    probe.spin_until(first_seen, 20, 'the first joint states on /tf')

    first = {t.child_frame_id: t for t in moving[0].transforms}
    # Revolute, continuous, prismatic move on /tf (prefixed); the floating joint is skipped.
    assert {(t.header.frame_id, c) for c, t in first.items()} == {
        ('robot1/base', 'robot1/arm'), ('robot1/arm', 'robot1/wheel'),
        ('robot1/base', 'robot1/slider')}
    arm, wheel, slider = (first[f'robot1/{c}'].transform for c in ('arm', 'wheel', 'slider'))
    assert (arm.translation.z, arm.rotation.z, arm.rotation.w) == pytest.approx(
        (0.5, math.sin(0.25), math.cos(0.25)))  # 0.5 rad about z
    assert (wheel.translation.x, wheel.rotation.y, wheel.rotation.w) == pytest.approx(
        (0.2, math.sin(0.5), math.cos(0.5)))  # 1.0 rad about y
    assert (slider.translation.x, slider.translation.z, slider.rotation.w) == pytest.approx(
        (0.25, 0.1, 1.0))  # 0.25 m along x

    # publish_frequency 2.0: a joint state less than 0.5 s (by its stamp) after the last
    # published one is dropped.
    for offset in (0.1, 0.2, 0.6, 0.7, 1.2):
        send(offset, offset)
    probe.spin_until(lambda: 1.2 in stamps_seen(), 15, 'the joint states stamped +1.2 s')
    assert stamps_seen() == [0.0, 0.6, 1.2]

    # publish_frequency is bounded as upstream's; ignore_timestamp takes every message.
    refused = set_parameter(probe, 'publish_frequency', 2000.0)
    assert (refused.successful, refused.reason) == (
        False, 'publish_frequency must be between 0.0 and 1000.0')
    assert set_parameter(probe, 'ignore_timestamp', True).successful
    for offset in (1.3, 1.4, 1.45):
        send(offset, offset)
    probe.spin_until(lambda: 1.45 in stamps_seen(), 15, 'the joint states stamped +1.45 s')
    assert stamps_seen() == [0.0, 0.6, 1.2, 1.3, 1.4, 1.45]
    assert 'Traceback' not in node.output
