"""urdf_tutorial as the Jazzy "URDF" pages use it: every model 01-08 is the robot the pages
build (links, joints, joint types), and `ros2 launch urdf_tutorial display.launch.py model:=...`
starts robot_state_publisher and joint_state_publisher with the model on /robot_description."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from ws_testing import REPO

URDF = REPO / 'src' / 'urdf_tutorial' / 'urdf'

LEGS = {'base_to_right_leg': ('fixed', 'base_link', 'right_leg'),
        'base_to_left_leg': ('fixed', 'base_link', 'left_leg')}
# "Building a visual robot model": the whole R2D2-like robot, every joint fixed.
VISUAL = {
    **LEGS,
    'right_base_joint': ('fixed', 'right_leg', 'right_base'),
    'right_front_wheel_joint': ('fixed', 'right_base', 'right_front_wheel'),
    'right_back_wheel_joint': ('fixed', 'right_base', 'right_back_wheel'),
    'left_base_joint': ('fixed', 'left_leg', 'left_base'),
    'left_front_wheel_joint': ('fixed', 'left_base', 'left_front_wheel'),
    'left_back_wheel_joint': ('fixed', 'left_base', 'left_back_wheel'),
    'gripper_extension': ('fixed', 'base_link', 'gripper_pole'),
    'left_gripper_joint': ('fixed', 'gripper_pole', 'left_gripper'),
    'left_tip_joint': ('fixed', 'left_gripper', 'left_tip'),
    'right_gripper_joint': ('fixed', 'gripper_pole', 'right_gripper'),
    'right_tip_joint': ('fixed', 'right_gripper', 'right_tip'),
    'head_swivel': ('fixed', 'base_link', 'head'),
    'tobox': ('fixed', 'head', 'box'),
}
# "Building a movable robot model": continuous wheels and head, a prismatic gripper pole,
# revolute grippers.
FLEXIBLE = {**VISUAL, **{name: ('continuous', *VISUAL[name][1:]) for name in (
    'right_front_wheel_joint', 'right_back_wheel_joint', 'left_front_wheel_joint',
    'left_back_wheel_joint', 'head_swivel')},
    'gripper_extension': ('prismatic', 'base_link', 'gripper_pole'),
    'left_gripper_joint': ('revolute', 'gripper_pole', 'left_gripper'),
    'right_gripper_joint': ('revolute', 'gripper_pole', 'right_gripper')}
MODELS = {
    '01-myfirst.urdf': {},
    '02-multipleshapes.urdf': {'base_to_right_leg': LEGS['base_to_right_leg']},
    '03-origins.urdf': {'base_to_right_leg': LEGS['base_to_right_leg']},
    '04-materials.urdf': LEGS,
    '05-visual.urdf': VISUAL,
    '06-flexible.urdf': FLEXIBLE,
    '07-physics.urdf': FLEXIBLE,
    '08-macroed.urdf.xacro': FLEXIBLE,
}


def expand(path: Path, env: dict[str, str] | None = None) -> str:
    """The URDF of a model as display.launch.py makes it (`xacro FILE`, plain URDF too)."""
    done = subprocess.run(['xacro', str(path)], capture_output=True, text=True, timeout=60,
                          env=env)
    assert (done.returncode, done.stderr) == (0, ''), done.stderr
    return done.stdout


@pytest.mark.parametrize('model', sorted(MODELS))
def test_each_model_is_the_robot_the_pages_build(model: str) -> None:
    from robot_state_publisher.urdf_model import parse
    text = (URDF / model).read_text() if model.endswith('.urdf') else expand(URDF / model)
    robot = parse(text)
    joints = {j.name: (j.type, j.parent, j.child) for j in robot.joints}
    assert joints == MODELS[model]
    assert robot.root == 'base_link'
    assert set(robot.links) == {'base_link'} | {child for _, _, child in joints.values()}
    assert len(robot.links) == {'01': 1, '02': 2, '03': 2, '04': 3}.get(model[:2], 16)


@pytest.mark.parametrize('model, gui', [('urdf/01-myfirst.urdf', None),
                                        ('urdf/08-macroed.urdf.xacro', 'false')])
def test_display_launch_runs_the_publishers_with_the_model(
        launch, probe, ros_env, tmp_path: Path, model: str, gui: str | None) -> None:
    from rclpy.qos import DurabilityPolicy, QoSProfile
    from robot_state_publisher.urdf_model import parse
    from sensor_msgs.msg import JointState
    from std_msgs.msg import String
    from tf2_msgs.msg import TFMessage
    # rviz2 (and the slider GUI) are pages of the web app: a private one, no browser.
    env = dict(ros_env, RQT_WEB_STATE_DIR=str(tmp_path / 'rqt'), BROWSER='')
    env.pop('DISPLAY', None)
    args = [f'model:={model}'] + ([f'gui:={gui}'] if gui else [])
    try:
        display = launch(argv=['ros2', 'launch', 'urdf_tutorial', 'display.launch.py', *args],
                         env=env)
        latched = QoSProfile(depth=10, durability=DurabilityPolicy.TRANSIENT_LOCAL)
        descriptions = probe.collect(String, '/robot_description', latched)
        states = probe.collect(JointState, '/joint_states')
        statics = probe.collect(TFMessage, '/tf_static', latched)

        def nodes() -> set[str]:
            return {name for name, _ns in probe.node.get_node_names_and_namespaces()}
        probe.spin_until(lambda: {'robot_state_publisher', 'joint_state_publisher'} <= nodes(),
                         40, 'robot_state_publisher and joint_state_publisher in the graph')
        probe.spin_until(lambda: descriptions, 30, '/robot_description')
        # The model on /robot_description, as `xacro FILE` expands the installed file.
        from ament_index_python.packages import get_package_share_directory
        share = Path(get_package_share_directory('urdf_tutorial'))
        assert descriptions[-1].data == expand(share / model, env)
        expected = MODELS[Path(model).name]
        robot = parse(descriptions[-1].data)
        assert {j.name: (j.type, j.parent, j.child) for j in robot.joints} == expected
        # joint_state_publisher: every movable joint, at 0 or its limits' centre (nothing
        # when there is none: upstream publishes only non-empty messages).
        movable = sorted(n for n, (kind, _, _) in expected.items() if kind != 'fixed')
        if movable:
            probe.spin_until(lambda: states, 30, '/joint_states')
            assert sorted(states[-1].name) == movable
        # gui defaults to true: the slider GUI (joint_state_publisher_gui, whose node is
        # joint_state_publisher) instead of the plain joint_state_publisher.
        publisher = 'joint_state_publisher' if gui == 'false' else 'joint_state_publisher_gui'
        display.wait_for_output(rf'^\[INFO\] \[{publisher}-\d+\]: process started', timeout=5)
        fixed = {(p, c) for kind, p, c in expected.values() if kind == 'fixed'}
        if fixed:
            probe.spin_until(lambda: {(t.header.frame_id, t.child_frame_id) for m in statics
                                      for t in m.transforms} >= fixed, 20,
                             'the fixed joints on /tf_static')
        display.wait_for_output(r'rviz2: RViz: http://127\.0\.0\.1:\d+/rviz\?token=\w+&config='
                                r'\S+/urdf_tutorial/rviz/urdf\.rviz', timeout=30)
        assert 'Traceback' not in display.output
    finally:
        subprocess.run(['rqt', '--stop'], env=env, capture_output=True, timeout=20)
