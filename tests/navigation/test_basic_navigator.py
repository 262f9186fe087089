"""BasicNavigator as a user's script drives it, against real Nav2 action and service servers.

Each test writes a small navigator script, runs it as its own process and reads what it logs
and prints; the servers (nav2_stand_in_servers.py, real rclpy servers under Nav2's names) print
what they received. Everything runs over DDS in a leased domain.
"""

from __future__ import annotations

import ast
import re
import sys
import textwrap
import time
from collections.abc import Callable
from pathlib import Path

import pytest

from support import RosProcess

SERVERS = Path(__file__).with_name('nav2_stand_in_servers.py')
# What every script starts with: a user's imports, a pose helper and the navigator.
PRELUDE = '''\
import rclpy
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Path
from nav2_simple_commander.robot_navigator import BasicNavigator, TaskResult


def pose(x, y):
    p = PoseStamped()
    p.header.frame_id = 'map'
    p.pose.position.x = float(x)
    p.pose.position.y = float(y)
    p.pose.orientation.w = 1.0
    return p


def finish(navigator, limit=300):
    # isTaskComplete waits up to 0.1 s: 300 polls bound a task to about 30 s.
    for _ in range(limit):
        if navigator.isTaskComplete():
            return navigator.getResult()
    return 'still running'


rclpy.init()
nav = BasicNavigator()
'''
EPILOGUE = '''
nav.destroyNode()
rclpy.shutdown()
print('script done')
'''
LOG = r'\[{level}\] \[\d+\.\d+\] \[basic_navigator\]: {message}'


def log_line(message: str, level: str = 'INFO') -> str:
    return LOG.format(level=level, message=re.escape(message))


def run_script(start: Callable[..., RosProcess], tmp_path: Path, body: str) -> RosProcess:
    script = tmp_path / f'navigator_script_{len(list(tmp_path.glob("*.py")))}.py'
    script.write_text(PRELUDE + textwrap.dedent(body) + EPILOGUE)
    return start(argv=[sys.executable, str(script)])


def finished(process: RosProcess, timeout: float = 60.0) -> str:
    """The script's whole output, once it printed its last line and exited 0."""
    process.wait_for_output('^script done$', timeout=timeout)
    assert process.wait(timeout=10) == 0, process.output
    return process.output


class Since:
    """Output lines a long-running process printed after this point (module-wide servers)."""

    def __init__(self, process: RosProcess) -> None:
        self.process = process
        self.offset = len(process.output)

    @property
    def text(self) -> str:
        return self.process.output[self.offset:]

    def wait_for(self, pattern: str, timeout: float = 10.0) -> re.Match[str]:
        deadline = time.monotonic() + timeout
        while not (match := re.search(pattern, self.text, re.MULTILINE)):
            if time.monotonic() > deadline:
                raise AssertionError(f'{pattern!r} not printed by the servers within '
                                     f'{timeout} s; they printed:\n{self.text}')
            time.sleep(0.05)
        return match


@pytest.fixture(scope='module')
def servers(module_launch: Callable[..., RosProcess]) -> RosProcess:
    process = module_launch(argv=[sys.executable, str(SERVERS)])
    process.wait_for_output('^stand-in servers ready$', timeout=30)
    return process


def test_go_to_pose_reports_feedback_and_succeeds(servers, module_launch, tmp_path):
    received = Since(servers)
    output = finished(run_script(module_launch, tmp_path, '''
        print('accepted:', nav.goToPose(pose(1.5, -2.0)))
        distances = []
        for _ in range(300):
            if nav.isTaskComplete():
                break
            feedback = nav.getFeedback()
            if feedback and feedback.distance_remaining not in distances:
                distances.append(feedback.distance_remaining)
        print('distances:', distances)
        print('result:', nav.getResult())
    '''))
    assert re.search(log_line('Navigating to goal: 1.5 -2.0...'), output), output
    assert 'accepted: True' in output and 'result: TaskResult.SUCCEEDED' in output
    distances = ast.literal_eval(re.search(r'^distances: (.*)$', output, re.M).group(1))
    assert distances and all(d in (3.0, 2.0, 1.0) for d in distances), distances
    assert distances == sorted(distances, reverse=True)
    received.wait_for(r"^navigate goal: 1\.5 -2 in map bt=''$")
    received.wait_for('^navigate succeeded$')


def test_aborted_navigation_is_failed_with_the_servers_error_code(servers, module_launch,
                                                                   tmp_path):
    output = finished(run_script(module_launch, tmp_path, '''
        nav.goToPose(pose(4, 4), behavior_tree='abort')
        print('result:', finish(nav), 'status:', nav.status)
        answer = nav.result_future.result().result
        print('error:', answer.error_code, answer.error_msg)
    '''))
    assert 'result: TaskResult.FAILED status: 6' in output, output  # STATUS_ABORTED
    assert 'error: 9999 stand-in abort' in output


def test_cancel_task_cancels_the_running_navigation(servers, module_launch, tmp_path):
    received = Since(servers)
    output = finished(run_script(module_launch, tmp_path, '''
        nav.goThroughPoses([pose(1, 1), pose(2, 2)], behavior_tree='slow')
        for _ in range(300):  # until the first feedback, at most about 30 s
            if nav.isTaskComplete() or nav.getFeedback() is not None:
                break
        print('feedback before cancel:', nav.getFeedback() is not None)
        nav.cancelTask()
        print('result:', finish(nav))
    '''))
    assert re.search(log_line('Navigating with 2 goals....'), output), output
    assert 'feedback before cancel: True' in output
    assert re.search(log_line('Canceling current task.'), output)
    assert 'result: TaskResult.CANCELED' in output
    received.wait_for('^navigate canceled$')


def test_rejected_goals_say_so_and_return_false(servers, module_launch, tmp_path):
    output = finished(run_script(module_launch, tmp_path, '''
        print('to pose accepted:', nav.goToPose(pose(1, 2), behavior_tree='reject'))
        print('through poses accepted:',
              nav.goThroughPoses([pose(1, 2), pose(3, 4)], behavior_tree='reject'))
        print('complete without a task:', nav.isTaskComplete())
    '''))
    assert re.search(log_line('Goal to 1.0 2.0 was rejected!', 'ERROR'), output), output
    assert re.search(log_line('Goal with 2 poses was rejected!', 'ERROR'), output)
    assert 'to pose accepted: False' in output and 'through poses accepted: False' in output
    assert 'complete without a task: True' in output


def test_lifecycle_startup_and_shutdown_call_every_manager(servers, module_launch, tmp_path):
    received = Since(servers)
    output = finished(run_script(module_launch, tmp_path, '''
        from nav2_msgs.srv import ManageLifecycleNodes
        # The managers must be in the graph before lifecycleStartup looks them up.
        for manager in ('lifecycle_manager_localization', 'lifecycle_manager_navigation'):
            client = nav.create_client(ManageLifecycleNodes, manager + '/manage_nodes')
            assert client.wait_for_service(timeout_sec=20), manager
        nav.lifecycleStartup()
        nav.lifecycleShutdown()
    '''))
    for line in ('Starting up lifecycle nodes based on lifecycle_manager.',
                 'Starting up /lifecycle_manager_localization/manage_nodes',
                 'Starting up /lifecycle_manager_navigation/manage_nodes',
                 'Nav2 is ready for use!',
                 'Shutting down lifecycle nodes based on lifecycle_manager.',
                 'Shutting down /lifecycle_manager_navigation/manage_nodes'):
        assert re.search(log_line(line), output), (line, output)
    for manager in ('localization', 'navigation'):
        received.wait_for(f'^lifecycle_manager_{manager} command: 0$')  # STARTUP
        received.wait_for(f'^lifecycle_manager_{manager} command: 4$')  # SHUTDOWN


def test_wait_until_nav2_active_sends_the_initial_pose_first(launch, tmp_path):
    lifecycle = launch(argv=[sys.executable, str(SERVERS), '--lifecycle'])
    lifecycle.wait_for_output('^stand-in servers ready$', timeout=30)
    output = finished(run_script(launch, tmp_path, '''
        nav.setInitialPose(pose(0.5, 0.25))
        nav.waitUntilNav2Active()
        print('initial pose received:', nav.initial_pose_received)
    '''))
    assert re.search(log_line('Publishing Initial Pose'), output), output
    assert 'initial pose received: True' in output
    ready = re.search(log_line('Nav2 is ready for use!'), output)
    assert ready, output
    lifecycle.wait_for_output('^initialpose: 0.5 0.25 in map$')
    # bt_navigator turned active only after amcl's pose: the navigator waited for it.
    assert 'bt_navigator active' in lifecycle.output
    # robot_localization is no lifecycle node and needs no initial pose: neither is waited for.
    output = finished(run_script(launch, tmp_path, '''
        nav.waitUntilNav2Active(navigator='amcl', localizer='robot_localization')
    '''))
    assert re.search(log_line('Nav2 is ready for use!'), output), output
    assert 'Initial Pose' not in output and 'initial pose' not in output


def test_behaviours_docking_and_path_queries(servers, module_launch, tmp_path):
    received = Since(servers)
    output = finished(run_script(module_launch, tmp_path, '''
        for task in (lambda: nav.spin(), lambda: nav.backup(),
                     lambda: nav.driveOnHeading(0.3, 0.1, 5), lambda: nav.assistedTeleop(),
                     lambda: nav.followWaypoints([pose(1, 0), pose(2, 0), pose(3, 0)]),
                     lambda: nav.dockRobotByID('dock1'), lambda: nav.undockRobot('charger')):
            print('sent:', task(), 'result:', finish(nav))
        path = nav.getPath(pose(0, 0), pose(4, 0))
        print('path xs:', [p.pose.position.x for p in path.poses])
        print('failed path:', nav.getPath(pose(0, 0), pose(4, 0), planner_id='abort'))
        through = nav.getPathThroughPoses(pose(0, 0), [pose(1, 0), pose(6, 0)])
        print('through path:', len(through.poses), through.poses[-1].pose.position.x)
        smoothed = nav.smoothPath(path)
        print('smoothed:', smoothed.header.frame_id, len(smoothed.poses))
        print('follow path:', nav.followPath(smoothed, controller_id='FollowPath'),
              finish(nav))
    '''))
    for line in ('Spinning to angle 1.57....', 'Backing up 0.15 m at 0.025 m/s....',
                 'Drive 0.3 m on heading at 0.1 m/s....', "Running 'assisted_teleop'....",
                 'Following 3 goals....', 'Docking at dock ID: dock1...',
                 'Undocking from dock of type: charger...', 'Getting path...',
                 'Smoothing path...', 'Executing path...'):
        assert re.search(log_line(line), output), (line, output)
    assert output.count('result: TaskResult.SUCCEEDED') == 7
    assert 'path xs: [0.0, 1.0, 2.0, 3.0, 4.0]' in output
    assert re.search(log_line('Getting path failed with status code: 6', 'WARN'), output)
    assert 'failed path: None' in output
    assert 'through path: 3 6.0' in output and 'smoothed: smoothed 5' in output
    assert 'follow path: True TaskResult.SUCCEEDED' in output
    # What reached the servers: upstream's defaults and the script's arguments.
    received.wait_for('^spin goal: target_yaw=1.57 time_allowance=10s')
    received.wait_for('^backup goal: target=0.15 speed=0.025 time_allowance=10s')
    received.wait_for('^drive_on_heading goal: target=0.3 speed=0.1 time_allowance=5s')
    received.wait_for('^assisted_teleop goal: time_allowance=30s')
    received.wait_for(r"^dock_robot goal: use_dock_id=True dock_id='dock1' .*"
                      r'navigate_to_staging_pose=True')
    received.wait_for(r"^compute_path_to_pose goal: 4 0 in map planner='abort' use_start=False")
    received.wait_for(r"^follow_path goal: path=path\[5\] controller_id='FollowPath' "
                      r"goal_checker_id=''")


def test_map_and_costmap_services(servers, module_launch, tmp_path):
    received = Since(servers)
    output = finished(run_script(module_launch, tmp_path, '''
        nav.changeMap('/maps/office.yaml')
        nav.changeMap('/maps/missing.pgm')
        nav.clearAllCostmaps()
        nav.clearCostmapAroundRobot(1.5)
        costmap = nav.getGlobalCostmap()
        print('global:', costmap.header.frame_id, costmap.metadata.size_x,
              costmap.metadata.size_y, list(costmap.data))
        print('local:', nav.getLocalCostmap().header.frame_id)
    '''))
    assert re.search(log_line('Change map request was successful!'), output), output
    assert re.search(log_line('Change map request failed!', 'ERROR'), output)
    assert 'global: map 3 2 [0, 0, 254, 0, 100, 0]' in output and 'local: odom' in output
    received.wait_for('^load_map: /maps/office.yaml$')
    # clearAllCostmaps: the local costmap first, then the global one.
    received.wait_for('^clear local_costmap$\n^clear global_costmap$')
    received.wait_for('^clear around robot reset_distance=1.5$')


def test_a_script_started_before_nav2_waits_for_it(launch, tmp_path):
    script = run_script(launch, tmp_path, '''
        nav.goToPose(pose(2, 3))
        print('result:', finish(nav))
    ''')
    script.wait_for_output(log_line("'NavigateToPose' action server not available, waiting..."),
                           timeout=30)
    launch(argv=[sys.executable, str(SERVERS)])
    output = finished(script)
    assert re.search(log_line('Navigating to goal: 2.0 3.0...'), output)
    assert 'result: TaskResult.SUCCEEDED' in output


def test_bad_numbers_are_refused_naming_the_argument_before_anything_is_sent(
        servers, module_launch, tmp_path):
    received = Since(servers)
    output = finished(run_script(module_launch, tmp_path, '''
        for call in (lambda: nav.spin(spin_dist='a lot'),
                     lambda: nav.spin(time_allowance=-1),
                     lambda: nav.backup(backup_speed=float('nan')),
                     lambda: nav.driveOnHeading(dist=True),
                     lambda: nav.clearCostmapAroundRobot(float('inf'))):
            try:
                call()
                print('sent')
            except ValueError as error:
                print('refused:', error)
        print('good spin:', nav.spin(0.5), finish(nav))
    '''))
    refusals = re.findall('^refused: (.*)$', output, re.MULTILINE)
    assert refusals == [
        "spin_dist must be a finite number (int or float), got 'a lot'",
        'time_allowance must be >= 0 s, got -1',
        'backup_speed must be a finite number (int or float), got nan',
        'dist must be a finite number (int or float), got True',
        'reset_distance must be a finite number (int or float), got inf'], output
    assert 'good spin: True TaskResult.SUCCEEDED' in output
    received.wait_for('^spin goal: target_yaw=0.5 ')
    # Only the good spin reached a server: the refused calls sent nothing.
    reached = re.findall('^(?:spin|backup|drive_on_heading) goal|^clear', received.text, re.M)
    assert reached == ['spin goal'], received.text
