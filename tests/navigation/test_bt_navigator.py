"""bt_navigator over real DDS: the default trees plan with the real planner_server on a
map from the real map_server, follow with a stand-in follow_path (bt_navigator_stand_ins.py,
also spin/backup/wait and the local costmap's clear service), TF static map -> odom ->
base_link with the robot at (1, 1); bt_navigator reads Jazzy's nav2_params.yaml section as
it is.

The map (6 m x 4 m): a border, and a solid block at x >= 4.0, y >= 2.4 (a goal inside it
has no path). The stand-in follows a path ending at x >= 4.0 until canceled or replaced.
"""

from __future__ import annotations

import math
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest
from action_msgs.msg import GoalStatus
from geometry_msgs.msg import PoseStamped
from nav2_msgs.action import ComputePathToPose, NavigateThroughPoses, NavigateToPose
from nav2_msgs.msg import BehaviorTreeLog
from rclpy.action import ActionClient

from support import TestNode, wait_until

WIDTH, HEIGHT = 120, 80  # cells of 5 cm
STAND_INS = Path(__file__).with_name('bt_navigator_stand_ins.py')

# bt_navigator's section of Nav2 Jazzy's nav2_bringup/params/nav2_params.yaml (its values).
NAVIGATOR_PARAMS = """\
bt_navigator:
  ros__parameters:
    global_frame: map
    robot_base_frame: base_link
    odom_topic: /odom
    bt_loop_duration: 10
    default_server_timeout: 20
    wait_for_service_timeout: 1000
    action_server_result_timeout: 900.0
    navigators: ["navigate_to_pose", "navigate_through_poses"]
    navigate_to_pose:
      plugin: "nav2_bt_navigator::NavigateToPoseNavigator"
    navigate_through_poses:
      plugin: "nav2_bt_navigator::NavigateThroughPosesNavigator"
    error_code_names:
      - compute_path_error_code
      - follow_path_error_code
"""
PLANNER_PARAMS = """\
planner_server:
  ros__parameters:
    expected_planner_frequency: 20.0
    planner_plugins: ["GridBased"]
    GridBased:
      plugin: "nav2_navfn_planner::NavfnPlanner"
      tolerance: 0.5
global_costmap:
  global_costmap:
    ros__parameters:
      update_frequency: 2.0
      global_frame: map
      robot_base_frame: base_link
      robot_radius: 0.15
      resolution: 0.05
      plugins: ["static_layer", "inflation_layer"]
      static_layer:
        plugin: "nav2_costmap_2d::StaticLayer"
        map_subscribe_transient_local: true
      inflation_layer:
        plugin: "nav2_costmap_2d::InflationLayer"
        inflation_radius: 0.4
"""
CHECKS_TREE = """\
<root BTCPP_format="4" main_tree_to_execute="MainTree">
  <BehaviorTree ID="MainTree">
    <Sequence>
      <ComputePathToPose goal="{goal}" path="{path}"/>
      <GetPoseFromPath path="{path}" index="-1" pose="{end}"/>
      <ArePosesNear ref_pose="{end}" target_pose="{goal}" tolerance="0.1"/>
      <CancelControl/>
    </Sequence>
  </BehaviorTree>
</root>
"""
UNKNOWN_NODE_TREE = """\
<root BTCPP_format="4" main_tree_to_execute="MainTree">
  <BehaviorTree ID="MainTree">
    <Sequence>
      <Teleport where="{goal}"/>
    </Sequence>
  </BehaviorTree>
</root>
"""


def write_map(directory: Path) -> Path:
    walls = np.zeros((HEIGHT, WIDTH), dtype=bool)
    walls[0, :] = walls[-1, :] = walls[:, 0] = walls[:, -1] = True
    walls[48:, 80:] = True  # the block: x >= 4.0 m, y >= 2.4 m
    pixels = np.where(walls, 0, 254).astype(np.uint8)[::-1]
    (directory / 'room.pgm').write_bytes(
        f'P5\n{WIDTH} {HEIGHT}\n255\n'.encode() + pixels.tobytes())
    yaml = directory / 'room.yaml'
    yaml.write_text('image: room.pgm\nmode: trinary\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\n'
                    'negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.25\n')
    return yaml


@pytest.fixture(scope='module')
def stack(module_launch, module_ros_env, tmp_path_factory):
    directory = tmp_path_factory.mktemp('bt_navigator')
    (directory / 'params.yaml').write_text(NAVIGATOR_PARAMS + PLANNER_PARAMS)
    params = str(directory / 'params.yaml')
    module_launch('nav2_map_server', 'map_server', '--ros-args',
                  '-p', f'yaml_filename:={write_map(directory)}')
    module_launch('tf2_ros', 'static_transform_publisher', '--frame-id', 'map',
                  '--child-frame-id', 'odom')
    module_launch('tf2_ros', 'static_transform_publisher', '--x', '1', '--y', '1',
                  '--frame-id', 'odom', '--child-frame-id', 'base_link')
    stand_ins = module_launch(argv=[sys.executable, str(STAND_INS)])
    stand_ins.wait_for_output('stand-ins ready', timeout=20.0)
    module_launch('nav2_planner', 'planner_server', '--ros-args', '--params-file', params)
    navigator = module_launch('nav2_bt_navigator', 'bt_navigator', '--ros-args',
                              '--params-file', params)
    manager = module_launch('nav2_lifecycle_manager', 'lifecycle_manager', '--ros-args', '-p',
                            "node_names:=['map_server', 'planner_server', 'bt_navigator']",
                            '-p', 'autostart:=true')
    manager.wait_for_output('Managed nodes are active', timeout=60.0)
    probe = TestNode(int(module_ros_env['ROS_DOMAIN_ID']))
    # the global costmap needs its map before a plan: wait until the planner answers one
    client = ActionClient(probe.node, ComputePathToPose, 'compute_path_to_pose')
    assert client.wait_for_server(timeout_sec=15.0)
    future = client.send_goal_async(ComputePathToPose.Goal(goal=pose(2.0, 1.0)))
    probe.spin_until(future.done, 10.0, 'the planner to take a goal')
    result = future.result().get_result_async()
    probe.spin_until(result.done, 20.0, 'a first plan')
    client.destroy()
    yield navigator, stand_ins, probe, directory
    probe.close()


def pose(x: float, y: float, frame: str = 'map') -> PoseStamped:
    msg = PoseStamped()
    msg.header.frame_id = frame
    msg.pose.position.x, msg.pose.position.y = x, y
    msg.pose.orientation.w = 1.0
    return msg


class Navigation:
    """One goal sent by the probe: its handle, feedback and result."""

    def __init__(self, probe: TestNode, client: ActionClient, goal) -> None:
        self.probe, self.feedback = probe, []
        future = client.send_goal_async(goal, lambda msg: self.feedback.append(msg.feedback))
        probe.spin_until(future.done, 10.0, 'the goal to be answered')
        self.handle = future.result()
        assert self.handle.accepted
        self.result = self.handle.get_result_async()

    def finish(self, timeout: float = 30.0) -> tuple[int, object]:
        self.probe.spin_until(self.result.done, timeout, 'the navigation result')
        return self.result.result().status, self.result.result().result


@pytest.fixture
def navigate(stack):
    _navigator, _stand_ins, probe, _directory = stack
    clients = {}

    def send(goal, action=NavigateToPose, name='navigate_to_pose') -> Navigation:
        if name not in clients:
            clients[name] = ActionClient(probe.node, action, name)
            assert clients[name].wait_for_server(timeout_sec=10.0)
        return Navigation(probe, clients[name], goal)

    yield send
    for client in clients.values():
        client.destroy()


def test_navigate_to_pose_plans_then_follows_with_feedback(stack, navigate):
    navigator, stand_ins, probe, _directory = stack
    logs = probe.collect(BehaviorTreeLog, '/behavior_tree_log')
    run = navigate(NavigateToPose.Goal(pose=pose(2.5, 1.5)))
    status, result = run.finish()
    assert status == GoalStatus.STATUS_SUCCEEDED, result.error_msg
    assert result.error_code == 0
    navigator.wait_for_output(r'Begin navigating from current location \(1\.00, 1\.00\) to '
                              r'\(2\.50, 1\.50\)')
    navigator.wait_for_output(r'\[bt_navigator\]: Goal succeeded')
    # Jazzy's bt_navigator section as it is: every parameter known, no warning
    assert 'Ignoring unknown parameter' not in navigator.output
    assert 'Error_code parameters were set to: compute_path_error_code follow_path_error_code' \
        in navigator.output
    stand_ins.wait_for_output(r"follow_path goal: \d+ poses to \(2\.50, 1\.50\) "
                              r"controller='FollowPath'")
    assert run.feedback, 'no feedback'
    last = run.feedback[-1]
    assert last.current_pose.header.frame_id == 'map'
    assert (last.current_pose.pose.position.x, last.current_pose.pose.position.y) == (1.0, 1.0)
    # the path from (1, 1) to (2.5, 1.5): at least the straight line, not much more
    straight = math.hypot(1.5, 0.5)
    assert straight - 0.05 <= last.distance_remaining < straight + 0.5
    assert last.number_of_recoveries == 0
    assert last.navigation_time.sec + last.navigation_time.nanosec * 1e-9 > 0.0
    # the tree's status changes on behavior_tree_log: planned, then followed
    def changes() -> list[tuple[str, str]]:
        return [(e.node_name, e.current_status) for log in logs for e in log.event_log]

    probe.spin_until(lambda: ('NavigateRecovery', 'SUCCESS') in changes(), 5.0,
                     "the tree's root to succeed on behavior_tree_log")
    assert ('ComputePathToPose', 'SUCCESS') in changes()
    assert ('FollowPath', 'RUNNING') in changes()


def test_basic_navigator_go_to_pose_and_through_poses(stack, module_launch):
    _navigator, stand_ins, _probe, directory = stack
    script = directory / 'commander.py'
    script.write_text(textwrap.dedent('''\
        import rclpy
        from geometry_msgs.msg import PoseStamped
        from nav2_simple_commander.robot_navigator import BasicNavigator, TaskResult

        def pose(x, y):
            p = PoseStamped()
            p.header.frame_id = 'map'
            p.pose.position.x, p.pose.position.y, p.pose.orientation.w = x, y, 1.0
            return p

        rclpy.init()
        nav = BasicNavigator()
        for send in (lambda: nav.goToPose(pose(2.0, 2.0)),
                     lambda: nav.goThroughPoses([pose(1.5, 2.0), pose(3.0, 1.5)])):
            send()
            feedback = None
            for _ in range(300):  # isTaskComplete waits up to 0.1 s: at most ~30 s
                if nav.isTaskComplete():
                    break
                feedback = nav.getFeedback() or feedback
            print('result', nav.getResult() == TaskResult.SUCCEEDED,
                  'feedback', feedback is not None, flush=True)
        nav.goToPose(pose(4.5, 1.5))  # the stand-in follows this path until canceled
        for _ in range(100):
            if nav.getFeedback() is not None:
                break
            nav.isTaskComplete()
        nav.cancelTask()
        for _ in range(100):
            if nav.isTaskComplete():
                break
        print('canceled', nav.getResult() == TaskResult.CANCELED, flush=True)
        nav.destroyNode()
        rclpy.shutdown()
    '''))
    process = module_launch(argv=[sys.executable, str(script)])
    assert process.wait(timeout=90) == 0, process.output
    assert process.output.count('result True feedback True') == 2, process.output
    assert 'canceled True' in process.output, process.output
    stand_ins.wait_for_output(r'follow_path goal: \d+ poses to \(3\.00, 1\.50\)')


def test_a_pose_on_goal_pose_navigates(stack):
    navigator, stand_ins, probe, _directory = stack
    publisher = probe.node.create_publisher(PoseStamped, 'goal_pose', 10)
    succeeded = navigator.output.count('Goal succeeded')
    try:
        probe.spin_until(lambda: publisher.get_subscription_count() > 0, 10.0,
                         "bt_navigator's goal_pose subscription")
        publisher.publish(pose(2.2, 1.2))  # as RViz's "2D Goal Pose" tool sends it
        navigator.wait_for_output(r'to \(2\.20, 1\.20\)')
        stand_ins.wait_for_output(r'follow_path goal: \d+ poses to \(2\.20, 1\.20\)')
        wait_until(lambda: navigator.output.count('Goal succeeded') > succeeded, 15.0,
                   'the navigation to succeed')
    finally:
        probe.node.destroy_publisher(publisher)


def test_second_goal_preempts_and_cancel_ends_canceled(stack, navigate):
    navigator, stand_ins, probe, _directory = stack
    first = navigate(NavigateToPose.Goal(pose=pose(4.5, 1.0)))
    stand_ins.wait_for_output(r'follow_path goal: \d+ poses to \(4\.50, 1\.00\)')
    second = navigate(NavigateToPose.Goal(pose=pose(4.5, 2.0)))
    status, _ = first.finish()
    assert status == GoalStatus.STATUS_ABORTED  # preempted, as Nav2's SimpleActionServer
    navigator.wait_for_output('Received goal preemption request')
    navigator.wait_for_output(r'to \(4\.50, 2\.00\)')
    # the tree saw the new goal: the controller now follows a path to it
    stand_ins.wait_for_output(r'follow_path goal: \d+ poses to \(4\.50, 2\.00\)', timeout=15)
    cancel = second.handle.cancel_goal_async()
    probe.spin_until(cancel.done, 10.0, 'the cancel answer')
    status, _ = second.finish()
    assert status == GoalStatus.STATUS_CANCELED
    stand_ins.wait_for_output('follow_path canceled')
    navigator.wait_for_output(r'\[bt_navigator\]: Goal canceled')


def test_unreachable_goal_aborts_with_the_planner_error_code(stack, navigate):
    navigator, stand_ins, _probe, _directory = stack
    run = navigate(NavigateToPose.Goal(pose=pose(5.0, 3.2)))
    status, result = run.finish(timeout=60.0)
    assert status == GoalStatus.STATUS_ABORTED
    assert result.error_code == ComputePathToPose.Result.NO_VALID_PATH
    assert result.error_msg == 'Failed to create plan with tolerance of: 0.500000'
    navigator.wait_for_output(r'\[bt_navigator\]: Goal failed')
    # the recoveries of the default tree ran in turn before it gave up
    for line in ('clear local costmap', 'spin goal', 'wait goal', 'backup goal'):
        stand_ins.wait_for_output(line)
    assert run.feedback[-1].number_of_recoveries >= 3


def test_unknown_bt_node_aborts_naming_its_line(stack, navigate):
    navigator, _stand_ins, _probe, directory = stack
    tree = directory / 'unknown_node.xml'
    tree.write_text(UNKNOWN_NODE_TREE)
    run = navigate(NavigateToPose.Goal(pose=pose(2.0, 1.0), behavior_tree=str(tree)))
    status, result = run.finish()
    assert status == GoalStatus.STATUS_ABORTED
    assert 'Error at line 4: -> Node not recognized: Teleport' in result.error_msg
    navigator.wait_for_output(r'Exception when loading BT: Error at line 4: -> Node not '
                              r'recognized: Teleport')
    # the default tree is still there for the next goal
    status, result = navigate(NavigateToPose.Goal(pose=pose(2.0, 1.2))).finish()
    assert status == GoalStatus.STATUS_SUCCEEDED, result.error_msg


def test_bad_goals_abort_with_one_line(stack, navigate):
    navigator, _stand_ins, _probe, _directory = stack
    status, result = navigate(NavigateToPose.Goal(pose=pose(2.0, 1.0, 'moon'))).finish()
    assert status == GoalStatus.STATUS_ABORTED
    assert result.error_msg == ("Failed to transform a goal pose provided with frame_id 'moon' "
                                "to the global frame 'map'.")
    navigator.wait_for_output(r"\[ERROR\].*Failed to transform a goal pose provided with "
                              r"frame_id 'moon'")
    status, result = navigate(NavigateThroughPoses.Goal(poses=[pose(2.0, float('nan'))]),
                              NavigateThroughPoses, 'navigate_through_poses').finish()
    assert status == GoalStatus.STATUS_ABORTED
    assert 'is not finite' in result.error_msg


def test_a_goal_tree_of_other_nav2_nodes_cancels_the_controller(stack, navigate):
    from nav2_msgs.action import FollowPath

    _navigator, stand_ins, probe, directory = stack
    follow = ActionClient(probe.node, FollowPath, 'follow_path')
    try:
        assert follow.wait_for_server(timeout_sec=10.0)
        path = ComputePathToPose.Result().path
        path.poses = [pose(4.0, 1.0), pose(4.5, 1.0)]  # the stand-in follows it until canceled
        running = Navigation(probe, follow, FollowPath.Goal(path=path))
        stand_ins.wait_for_output(r'follow_path goal: 2 poses to \(4\.50, 1\.00\)')
        tree = directory / 'checks.xml'
        tree.write_text(CHECKS_TREE)
        status, result = navigate(NavigateToPose.Goal(pose=pose(2.0, 1.4),
                                                      behavior_tree=str(tree))).finish()
        assert status == GoalStatus.STATUS_SUCCEEDED, result.error_msg
        status, _ = running.finish()
        assert status == GoalStatus.STATUS_CANCELED  # by CancelControl
    finally:
        follow.destroy()


def test_a_shipped_tree_by_its_path_drives_the_calibration_square(stack, navigate):
    from ament_index_python.packages import get_package_share_directory

    _navigator, stand_ins, _probe, _directory = stack
    tree = Path(get_package_share_directory('nav2_bt_navigator'),
                'behavior_trees', 'odometry_calibration.xml')
    drives, spins = (stand_ins.output.count(f'{name} goal') for name in ('drive_on_heading',
                                                                        'spin'))
    status, result = navigate(NavigateToPose.Goal(pose=pose(1.0, 1.0),
                                                  behavior_tree=str(tree))).finish()
    assert status == GoalStatus.STATUS_SUCCEEDED, result.error_msg
    wait_until(lambda: stand_ins.output.count('drive_on_heading goal') == drives + 12, 5.0,
               '12 sides driven')
    assert stand_ins.output.count('spin goal') == spins + 12  # 3 squares of 4 turns
