"""joint_state_publisher and xacro as a learner runs them (real processes, a real probe)."""

from __future__ import annotations

import subprocess
import time

import pytest

from ws_testing import REPO, TestNode

DATA = REPO / 'tests' / 'data' / 'urdf'


def wait_until_spun(probe: TestNode, predicate, timeout: float, what: str) -> None:
    """Call `predicate` (which spins the probe itself) until it holds; fail after timeout."""
    deadline = time.monotonic() + timeout
    while not predicate():
        if time.monotonic() > deadline:
            raise AssertionError(f'timed out after {timeout} s waiting for {what}')


def test_joint_state_publisher_zeros_centres_mimic_and_sources(launch, probe):
    from sensor_msgs.msg import JointState
    path = DATA / 'test_arm.urdf'
    launch('joint_state_publisher', 'joint_state_publisher', str(path), '--ros-args',
           '-p', 'source_list:=[/arm_source]', '-p', 'zeros.wheel_joint:=0.25')
    states = probe.collect(JointState, '/joint_states')
    probe.spin_until(lambda: states, 15, 'the first /joint_states')
    first = dict(zip(states[-1].name, states[-1].position, strict=True))
    # 0 inside the limits; the centre when 0 is outside; zeros.<joint>; mimic = 2 * 0 + 0.1.
    assert first == pytest.approx({'elbow_joint': 0.0, 'slide_joint': 1.0,
                                   'follow_joint': 0.1, 'wheel_joint': 0.25})
    assert states[-1].name == ['elbow_joint', 'slide_joint', 'follow_joint', 'wheel_joint']
    source = probe.node.create_publisher(JointState, '/arm_source', 10)

    def moved() -> bool:
        source.publish(JointState(name=['elbow_joint'], position=[0.4]))
        probe.spin_for(0.2)
        last = dict(zip(states[-1].name, states[-1].position, strict=True))
        return abs(last['follow_joint'] - 0.9) < 1e-9 and abs(last['elbow_joint'] - 0.4) < 1e-9
    wait_until_spun(probe, moved, 15, 'elbow_joint = 0.4 from /arm_source, mimic 0.9')


def test_xacro_expands_the_macroed_model():
    share = REPO / 'src' / 'urdf_tutorial' / 'urdf'
    done = subprocess.run(['xacro', str(share / '08-macroed.urdf.xacro')], capture_output=True,
                          text=True, timeout=60)
    assert done.returncode == 0 and done.stderr == '', done.stderr
    from robot_state_publisher.urdf_model import parse
    model = parse(done.stdout)
    assert sorted(model.moving()) == sorted([
        'gripper_extension', 'head_swivel', 'left_gripper_joint', 'right_gripper_joint',
        'left_front_wheel_joint', 'left_back_wheel_joint', 'right_front_wheel_joint',
        'right_back_wheel_joint'])
    assert len(model.links) == 16
