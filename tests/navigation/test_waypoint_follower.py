"""waypoint_follower over real DDS against a scripted navigate_to_pose server
(tests/navigation/navigate_to_pose_stand_in.py: the pose's z says whether a waypoint is
reached, fails with error code 105, is rejected or takes until canceled).

Two followers run: `/waypoint_follower` with Nav2's params (stop_on_failure false,
WaitAtWaypoint 200 ms), brought up by lifecycle_manager, and `/strict/waypoint_follower`
with stop_on_failure true, started by autostart_node, next to a stand-in of its own.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
from action_msgs.msg import GoalStatus
from geometry_msgs.msg import PoseStamped
from nav2_msgs.action import FollowWaypoints
from rcl_interfaces.srv import SetParameters
from rclpy.action import ActionClient
from rclpy.parameter import Parameter

from support import TestNode

STAND_IN = Path(__file__).with_name('navigate_to_pose_stand_in.py')
ABORT_CODE = 105  # the stand-in's error code for an unreachable waypoint
PARAMS = """\
waypoint_follower:
  ros__parameters:
    loop_rate: 20
    stop_on_failure: false
    action_server_result_timeout: 900.0
    waypoint_task_executor_plugin: "wait_at_waypoint"
    wait_at_waypoint:
      plugin: "nav2_waypoint_follower::WaitAtWaypoint"
      enabled: True
      waypoint_pause_duration: 200
"""
REACHED, FAILS, REJECTED, SLOW = 0.0, -1.0, -2.0, 1.0  # the stand-in's meaning of z


def pose(x: float, y: float, z: float = REACHED) -> PoseStamped:
    msg = PoseStamped()
    msg.header.frame_id = 'map'
    msg.pose.position.x, msg.pose.position.y, msg.pose.position.z = float(x), float(y), z
    msg.pose.orientation.w = 1.0
    return msg


@pytest.fixture(scope='module')
def stack(module_launch, module_ros_env, tmp_path_factory):
    params = tmp_path_factory.mktemp('waypoints') / 'nav2_params.yaml'
    params.write_text(PARAMS)
    navigator = module_launch(argv=[sys.executable, str(STAND_IN)])
    follower = module_launch('nav2_waypoint_follower', 'waypoint_follower', '--ros-args',
                             '--params-file', str(params))
    strict_navigator = module_launch(argv=[sys.executable, str(STAND_IN), '--ros-args',
                                           '-r', '__ns:=/strict'])
    strict = module_launch('nav2_waypoint_follower', 'waypoint_follower', '--ros-args',
                           '-r', '__ns:=/strict', '-p', 'stop_on_failure:=true',
                           '-p', 'autostart_node:=true')
    manager = module_launch('nav2_lifecycle_manager', 'lifecycle_manager', '--ros-args',
                            '-p', "node_names:=['waypoint_follower']", '-p', 'autostart:=true')
    manager.wait_for_output('Managed nodes are active', timeout=40.0)
    strict.wait_for_output(r'\[strict\.waypoint_follower\]: Activating', timeout=30.0)
    navigator.wait_for_output('navigate_to_pose ready', timeout=30.0)
    strict_navigator.wait_for_output('navigate_to_pose ready', timeout=30.0)
    probe = TestNode(int(module_ros_env['ROS_DOMAIN_ID']))
    clients: dict[str, ActionClient] = {}
    yield navigator, follower, (strict, strict_navigator), probe, clients
    for client in clients.values():
        client.destroy()
    probe.close()


def follow(stack: Any, poses: list[PoseStamped], name: str = '/follow_waypoints',
           cancel_at: int | None = None) -> tuple[int, Any, list[int]]:
    """Send a follow_waypoints goal; the status, result and the feedback's indices."""
    _navigator, _follower, _strict, probe, clients = stack
    if name not in clients:
        clients[name] = ActionClient(probe.node, FollowWaypoints, name)
        assert clients[name].wait_for_server(timeout_sec=20.0), f'{name} is missing'
    seen: list[int] = []
    future = clients[name].send_goal_async(
        FollowWaypoints.Goal(poses=poses),
        feedback_callback=lambda msg: seen.append(msg.feedback.current_waypoint))
    probe.spin_until(future.done, 10.0, 'the goal to be answered')
    handle = future.result()
    assert handle.accepted
    if cancel_at is not None:
        probe.spin_until(lambda: cancel_at in seen, 10.0, f'waypoint {cancel_at} under way')
        cancel = handle.cancel_goal_async()
        probe.spin_until(cancel.done, 10.0, 'the cancel answer')
    result = handle.get_result_async()
    probe.spin_until(result.done, 30.0, 'the result')
    return result.result().status, result.result().result, seen


def visits(navigator: Any, count: int) -> list[str]:
    """The last `count` goals the stand-in received, as 'x y'."""
    lines = [line.split(': ', 1)[1] for line in navigator.output.splitlines()
             if line.startswith('navigate_to_pose goal: ')]
    return lines[-count:]


def test_waypoints_are_visited_in_order(stack):
    navigator, follower, *_ = stack
    status, result, seen = follow(stack, [pose(1, 0), pose(2, 1), pose(3, 2)])
    assert status == GoalStatus.STATUS_SUCCEEDED
    assert list(result.missed_waypoints) == []
    navigator.wait_for_output('navigate_to_pose succeeded: 3 2')
    assert visits(navigator, 3) == ['1 0', '2 1', '3 2']
    assert sorted(set(seen)) == [0, 1, 2] and seen == sorted(seen)
    follower.wait_for_output('Received follow waypoint request with 3 waypoints.')
    follower.wait_for_output("Arrived at 2'th waypoint, sleeping for 200 milliseconds")
    follower.wait_for_output('Completed all 3 waypoints requested.')


def test_a_failing_waypoint_is_missed_and_the_rest_continue(stack):
    navigator, follower, *_ = stack
    poses = [pose(1, 1), pose(4, 4, FAILS), pose(5, 5, REJECTED), pose(6, 6)]
    status, result, _seen = follow(stack, poses)
    assert status == GoalStatus.STATUS_SUCCEEDED
    missed = [(m.index, m.error_code, m.goal.pose.position.x) for m in result.missed_waypoints]
    assert missed == [(1, ABORT_CODE, 4.0), (2, 0, 5.0)]
    navigator.wait_for_output('navigate_to_pose succeeded: 6 6')
    assert visits(navigator, 4) == ['1 1', '4 4', '5 5', '6 6']
    follower.wait_for_output('Failed to process waypoint 1, moving to next.')
    follower.wait_for_output(r'\[ERROR\] .*navigate_to_pose action client failed to send goal '
                             r'to server\.')


def test_stop_on_failure_aborts_at_the_first_miss(stack):
    _navigator, _follower, (strict, navigator), _probe, _clients = stack
    poses = [pose(7, 0), pose(8, 0, FAILS), pose(9, 0)]
    status, result, _seen = follow(stack, poses, '/strict/follow_waypoints')
    assert status == GoalStatus.STATUS_ABORTED
    assert [(m.index, m.error_code) for m in result.missed_waypoints] == [(1, ABORT_CODE)]
    strict.wait_for_output('Failed to process waypoint 1 in waypoint list and stop on failure '
                           'is enabled. Terminating action.')
    assert visits(navigator, 2) == ['7 0', '8 0']
    assert '9 0' not in visits(navigator, 10)


def test_cancel_cancels_the_navigation_too(stack):
    navigator, *_ = stack
    status, _result, _seen = follow(stack, [pose(1, 2), pose(3, 4, SLOW), pose(5, 6)],
                                    cancel_at=1)
    assert status == GoalStatus.STATUS_CANCELED
    navigator.wait_for_output('navigate_to_pose canceled: 3 4')
    assert '5 6' not in visits(navigator, 1)


def test_empty_goal_is_aborted_with_upstreams_line(stack):
    _navigator, follower, *_ = stack
    status, _result, _seen = follow(stack, [])
    assert status == GoalStatus.STATUS_ABORTED
    follower.wait_for_output('Empty vector of waypoints passed to waypoint following action '
                             'potentially due to conversation failure or empty request.')


def test_basic_navigator_follow_waypoints(stack, module_ros_env, tmp_path):
    navigator, *_ = stack
    script = tmp_path / 'waypoints.py'
    script.write_text(
        'import rclpy\n'
        'from geometry_msgs.msg import PoseStamped\n'
        'from nav2_simple_commander.robot_navigator import BasicNavigator, TaskResult\n'
        'def pose(x, y):\n'
        '    p = PoseStamped()\n'
        "    p.header.frame_id = 'map'\n"
        '    p.pose.position.x, p.pose.position.y = float(x), float(y)\n'
        '    p.pose.orientation.w = 1.0\n'
        '    return p\n'
        'rclpy.init()\n'
        'nav = BasicNavigator()\n'
        'nav.followWaypoints([pose(11, 1), pose(12, 2)])\n'
        'indices = set()\n'
        'for _ in range(300):\n'
        '    if nav.isTaskComplete():\n'
        '        break\n'
        '    feedback = nav.getFeedback()\n'
        '    if feedback:\n'
        '        indices.add(feedback.current_waypoint)\n'
        'print("succeeded", nav.getResult() == TaskResult.SUCCEEDED, flush=True)\n'
        'print("feedback", sorted(indices), flush=True)\n'
        'nav.destroyNode()\n'
        'rclpy.shutdown()\n')
    done = subprocess.run([sys.executable, str(script)], env=module_ros_env,
                          capture_output=True, text=True, timeout=60)
    assert done.stdout.splitlines()[0] == 'succeeded True', done.stdout + done.stderr
    assert done.stdout.splitlines()[1] in ('feedback [0, 1]', 'feedback [1]'), done.stdout
    assert visits(navigator, 2) == ['11 1', '12 2']


def test_photo_at_waypoint_is_not_built(launch):
    follower = launch('nav2_waypoint_follower', 'waypoint_follower', '--ros-args',
                      '-p', 'autostart_node:=true',
                      '-p', 'waypoint_task_executor_plugin:=photo_at_waypoint',
                      '-p', 'photo_at_waypoint.plugin:=nav2_waypoint_follower::PhotoAtWaypoint')
    follower.wait_for_output(
        r'\[FATAL\] .*Failed to create waypoint_task_executor\. Exception: '
        r'nav2_waypoint_follower::PhotoAtWaypoint is not built in this workspace', timeout=20)
    follower.wait_for_output('Auto-starting node waypoint_follower failed to configure!')


def set_parameter(probe: TestNode, name: str, value: Any) -> Any:
    request = SetParameters.Request(parameters=[Parameter(name, value=value).to_parameter_msg()])
    return probe.call(SetParameters, '/waypoint_follower/set_parameters', request).results[0]


def test_stop_on_failure_and_loop_rate_change_at_run_time(stack):
    navigator, _follower, _strict, probe, _clients = stack
    assert set_parameter(probe, 'stop_on_failure', True).successful
    try:
        status, result, _seen = follow(stack, [pose(21, 0, FAILS), pose(22, 0)])
        assert status == GoalStatus.STATUS_ABORTED
        assert [m.index for m in result.missed_waypoints] == [0]
        assert '22 0' not in visits(navigator, 10)
    finally:
        assert set_parameter(probe, 'stop_on_failure', False).successful
    refused = set_parameter(probe, 'loop_rate', 0)
    assert not refused.successful and refused.reason == 'loop_rate must be > 0 Hz, got 0'
