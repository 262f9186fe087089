"""The Managed-nodes demo page as written: `ros2 run lifecycle lifecycle_talker` driven with
`ros2 lifecycle nodes|get|list|set` (ros2lifecycle's output; a transition the state does
not offer gets its one-line error and changes nothing), `ros2 launch lifecycle
lifecycle_demo_launch.py`, and launch_ros' LifecycleNode with LifecycleTransition."""

from __future__ import annotations

import textwrap

import pytest

from ws_testing import ros2

LIST_UNCONFIGURED = ('- configure [1]\n\tStart: unconfigured\n\tGoal: configuring\n'
                     '- shutdown [5]\n\tStart: unconfigured\n\tGoal: shuttingdown\n')


def test_ros2_lifecycle_verbs_drive_lc_talker(launch, ros_env):
    talker = launch(argv=['ros2', 'run', 'lifecycle', 'lifecycle_talker'], env=ros_env)
    # As on the page: `get` first (a named node is waited for while it is being discovered;
    # `nodes` lists what is known at once).
    assert ros2(ros_env, 'lifecycle', 'get', '/lc_talker').stdout == 'unconfigured [1]\n'
    nodes = ros2(ros_env, 'lifecycle', 'nodes')
    assert (nodes.returncode, nodes.stdout) == (0, '/lc_talker\n'), nodes.stderr
    assert ros2(ros_env, 'lifecycle', 'list', 'lc_talker').stdout == LIST_UNCONFIGURED
    graph = ros2(ros_env, 'lifecycle', 'list', 'lc_talker', '-a').stdout
    assert graph.count('\n- ') + 1 == 25 and graph.endswith(
        '- transition_error [62]\n\tStart: errorprocessing\n\tGoal: finalized\n'), graph

    # Not offered in this state: upstream's error, nothing asked of the node.
    bad = ros2(ros_env, 'lifecycle', 'set', '/lc_talker', 'activate')
    assert (bad.returncode, bad.stdout, bad.stderr) == (
        1, '', 'Unknown transition requested, available ones are:\n- configure [1]\n'
        '- shutdown [5]\n')
    assert ros2(ros_env, 'lifecycle', 'get', '/lc_talker').stdout == 'unconfigured [1]\n'

    done = ros2(ros_env, 'lifecycle', 'set', '/lc_talker', 'configure')
    assert (done.returncode, done.stdout) == (0, 'Transitioning successful\n'), done.stderr
    talker.wait_for_output(r'\[lc_talker\]: on_configure\(\) is called\.')
    talker.wait_for_output(r'Lifecycle publisher is currently inactive\. Messages are not '
                           r'published\.', timeout=5)
    assert ros2(ros_env, 'lifecycle', 'get').stdout == '/lc_talker: inactive [2]\n'

    # Straight to the service with a transition inactive does not have (5: unconfigured
    # shutdown): rclcpp's error line, success=False, and the node lives on.
    call = ros2(ros_env, 'service', 'call', '/lc_talker/change_state',
                'lifecycle_msgs/srv/ChangeState', '{transition: {id: 5}}')
    assert 'lifecycle_msgs.srv.ChangeState_Response(success=False)' in call.stdout, call
    talker.wait_for_output(r'\[ERROR\] .*\[lc_talker\]: Unable to start transition 5 from '
                           r'current state inactive: Transition is not registered\.')
    assert ros2(ros_env, 'lifecycle', 'set', 'lc_talker', '3').stdout == \
        'Transitioning successful\n'  # by id: activate
    talker.wait_for_output(r'Lifecycle publisher is active\. Publishing: '
                           r'\[Lifecycle HelloWorld #\d+\]', timeout=5)

    missing = ros2(ros_env, 'lifecycle', 'get', '/nobody', '--spin-time', '1')
    assert (missing.returncode, missing.stderr) == (1, 'Node not found\n')


def test_lifecycle_demo_launch_walks_lc_talker(launch, ros_env):
    run = launch(argv=['ros2', 'launch', 'lifecycle', 'lifecycle_demo_launch.py'], env=ros_env)
    run.wait_for_output(r'\[lc_client\]: Transition 1 successfully triggered\.', timeout=20)
    run.wait_for_output(r'\[lc_client\]: Node lc_talker has current state inactive\.')
    run.wait_for_output(r'\[lc_listener\]: notify callback: Transition from state unconfigured '
                        r'to configuring')
    run.wait_for_output(r'\[lc_listener\]: notify callback: Transition from state configuring '
                        r'to inactive')
    # lc_client waits 10 s between transitions and logs their ids (activate: 3); activating
    # takes lc_talker 2 s.
    run.wait_for_output(r'\[lc_client\]: Transition 3 successfully triggered\.', timeout=16)
    run.wait_for_output(r'\[lc_listener\]: data_callback: Lifecycle HelloWorld #\d+',
                        timeout=5)
    assert run.stop() == 0


def test_lifecycle_node_and_transition_actions(launch, ros_env, tmp_path):
    launch_file = tmp_path / 'managed_launch.py'
    launch_file.write_text(textwrap.dedent('''
        from launch import LaunchDescription
        from launch.actions import EmitEvent, LogInfo, RegisterEventHandler
        from launch.events import Shutdown
        from launch_ros.actions import LifecycleNode, LifecycleTransition
        from launch_ros.event_handlers import OnStateTransition
        from lifecycle_msgs.msg import Transition


        def generate_launch_description():
            return LaunchDescription([
                LifecycleNode(package='lifecycle_py', executable='lifecycle_talker',
                              name='lc_talker', namespace='', output='screen'),
                LifecycleTransition(lifecycle_node_names=['lc_talker'], transition_ids=[
                    Transition.TRANSITION_CONFIGURE, Transition.TRANSITION_ACTIVATE]),
                RegisterEventHandler(OnStateTransition(goal_state='active', entities=[
                    LogInfo(msg='lc_talker is active'), EmitEvent(event=Shutdown())])),
            ])
    '''))
    run = launch(argv=['ros2', 'launch', str(launch_file)], env=ros_env)
    run.wait_for_output(r'\[lc_talker\]: on_configure\(\) is called\.', timeout=20)
    run.wait_for_output(r'\[lc_talker\]: on_activate\(\) is called\.')
    run.wait_for_output(r'lc_talker is active')
    assert run.wait(timeout=15) == 0


def test_change_state_event_refuses_an_unknown_transition():
    from launch_ros.events.lifecycle import ChangeState, matches_node_name
    with pytest.raises(ValueError, match=r"given transition_id of '42', expected one of "
                       r'\{TRANSITION_CREATE: 0, TRANSITION_CONFIGURE: 1,'):
        ChangeState(lifecycle_node_matcher=matches_node_name('lc_talker'), transition_id=42)


def test_hidden_lifecycle_node_needs_include_hidden_nodes(launch, ros_env):
    """ros2lifecycle's fixture (simple_lifecycle_node) as its tests run it: one plain, one
    hidden. Hidden managed nodes are left out of every verb unless asked for."""
    fixture = ['ros2', 'run', 'ros2lifecycle_test_fixtures', 'simple_lifecycle_node']
    plain = launch(argv=fixture, env=ros_env)
    hidden = launch(argv=[*fixture, '--ros-args', '-r', '__node:=_hidden_test_lifecycle_node'],
                    env=ros_env)
    assert ros2(ros_env, 'lifecycle', 'get', '/test_lifecycle_node').stdout == \
        'unconfigured [1]\n'
    found = ros2(ros_env, 'lifecycle', 'get', '--include-hidden-nodes',
                 '/_hidden_test_lifecycle_node')
    assert (found.returncode, found.stdout) == (0, 'unconfigured [1]\n'), found.stderr
    for verb in (['get'], ['list'], ['set']):
        args = [*verb, '/_hidden_test_lifecycle_node'] + (['configure'] if verb == ['set'] else [])
        refused = ros2(ros_env, 'lifecycle', *args)
        assert (refused.returncode, refused.stderr) == (1, 'Node not found\n'), verb
    assert ros2(ros_env, 'lifecycle', 'nodes', '-c').stdout == '1\n'
    assert ros2(ros_env, 'lifecycle', 'nodes', '-a').stdout == \
        '/_hidden_test_lifecycle_node\n/test_lifecycle_node\n'
    assert ros2(ros_env, 'lifecycle', 'nodes', '-a', '-c').stdout == '2\n'

    for transition, line in (('configure', r'on_configure\(\) is called\.'),
                              ('activate', r'on_activate\(\) is called\.'),
                              ('deactivate', r'on_deactivate\(\) is called\.'),
                              ('cleanup', r'on cleanup is called\.')):
        done = ros2(ros_env, 'lifecycle', 'set', '--include-hidden-nodes',
                    '_hidden_test_lifecycle_node', transition)
        assert (done.returncode, done.stdout) == (0, 'Transitioning successful\n'), done.stderr
        hidden.wait_for_output(r'\[_hidden_test_lifecycle_node\]: ' + line)
    assert ros2(ros_env, 'lifecycle', 'get', '--include-hidden-nodes',
                '_hidden_test_lifecycle_node').stdout == 'unconfigured [1]\n'
    assert plain.popen.poll() is None and hidden.popen.poll() is None
