"""tf2_ros' executables as the tf2 pages type them, over real DDS: static_transform_publisher
(new and deprecated forms, bad input), tf2_echo's block (a listener started late still gets
the static frame: /tf_static is transient-local), tf2_monitor's report."""
from __future__ import annotations

import re
import time

from ws_testing import ros2_side_by_side

ECHO_BLOCK = re.compile(
    r'^At time 0\.0\n'
    r'- Translation: \[1\.000, 2\.000, 3\.000\]\n'
    r'- Rotation: in Quaternion \[0\.000, 0\.000, 0\.707, 0\.707\]\n'
    r'- Rotation: in RPY \(radian\) \[0\.000, -?0\.000, 1\.571\]\n'
    r'- Rotation: in RPY \(degree\) \[0\.000, -?0\.000, 90\.000\]\n'
    r'- Matrix:\n'
    r'  -?0\.000 -1\.000  0\.000  1\.000\n'
    r'  1\.000  -?0\.000  0\.000  2\.000\n'
    r'  0\.000  0\.000  1\.000  3\.000\n'
    r'  0\.000  0\.000  0\.000  1\.000\n', re.MULTILINE)


def test_static_transform_publisher_and_a_late_tf2_echo(launch) -> None:
    publisher = launch(argv=['ros2', 'run', 'tf2_ros', 'static_transform_publisher', '--x', '1',
                             '--y', '2', '--z', '3', '--yaw', '1.5707963267948966',
                             '--frame-id', 'world', '--child-frame-id', 'mystaticturtle'])
    publisher.wait_for_output(
        r"^\[INFO\] \[[\d.]+\] \[static_transform_publisher_[0-9a-zA-Z]{16}\]: Spinning until "
        r"stopped - publishing transform\ntranslation: \('1\.000000', '2\.000000', "
        r"'3\.000000'\)\nrotation: \('0\.000000', '0\.000000', '0\.707107', '0\.707107'\)\n"
        r"from 'world' to 'mystaticturtle'$", timeout=20)
    time.sleep(1.0)  # the one /tf_static message is long sent when the echo starts
    echo = launch(argv=['ros2', 'run', 'tf2_ros', 'tf2_echo', 'world', 'mystaticturtle', '5'])
    echo.wait_for_output(ECHO_BLOCK.pattern, timeout=20)
    assert echo.stop() == 0
    assert 'Traceback' not in echo.output
    assert publisher.stop() == 0


def test_static_transform_publisher_old_style_and_bad_input(launch, ros_env) -> None:
    old = launch(argv=['ros2', 'run', 'tf2_ros', 'static_transform_publisher',
                       '0', '0', '1', '0', '0', '0', 'world', 'mystaticturtle'])
    # Five commands refused at once, independent of each other and of `old`: all side by side.
    bad, both, same, usage, rate = ros2_side_by_side(
        ros_env,
        ['run', 'tf2_ros', 'static_transform_publisher', '--x', 'one', '--frame-id', 'a',
         '--child-frame-id', 'b'],
        ['run', 'tf2_ros', 'static_transform_publisher', '--yaw', '1', '--qw', '1',
         '--frame-id', 'a', '--child-frame-id', 'b'],
        ['run', 'tf2_ros', 'static_transform_publisher', '--frame-id', 'a',
         '--child-frame-id', 'a'],
        ['run', 'tf2_ros', 'tf2_echo', 'world'],
        ['run', 'tf2_ros', 'tf2_echo', 'a', 'b', '1.0foo'])
    old.wait_for_output(r'^\[WARN\] \[[\d.]+\] \[\]: Old-style arguments are deprecated; see '
                        r'--help for new-style arguments$', timeout=20)
    old.wait_for_output(r"translation: \('0\.000000', '0\.000000', '1\.000000'\)", timeout=20)
    assert old.stop() == 0

    assert bad.returncode == 1
    error = bad.stderr.split('[ros2run]')[0]
    assert re.fullmatch(r'\[ERROR\] \[[\d.]+\] \[\]: error parsing command line arguments: '
                        r'Failed to parse --x argument as float\n', error), error
    assert bad.stdout.startswith('usage: static_transform_publisher [--x X]')
    assert 'Cannot specify both quaternion and Euler rotations' in both.stderr
    assert same.returncode == 1
    assert "cannot publish static transform from 'a' to 'a', exiting" in same.stderr
    assert usage.returncode == 1
    assert usage.stdout.startswith('Usage: tf2_echo source_frame target_frame [echo_rate]\n')
    assert rate.returncode == 2
    assert rate.stderr.startswith(
        "Failed to convert rate argument '1.0foo' to a floating-point number\n")


def test_tf2_echo_waits_for_a_missing_frame_and_says_why(launch) -> None:
    echo = launch(argv=['ros2', 'run', 'tf2_ros', 'tf2_echo', 'world', 'turtle9'])
    echo.wait_for_output(
        r'^\[INFO\] \[[\d.]+\] \[tf2_echo\]: Waiting for transform world ->  turtle9: Invalid '
        r'frame ID "world" passed to canTransform argument target_frame - frame does not exist$',
        timeout=20)
    assert echo.stop() == 0


def test_tf2_monitor_reports_the_chain(launch) -> None:
    launch(argv=['ros2', 'run', 'tf2_ros', 'static_transform_publisher', '--z', '1',
                 '--frame-id', 'world', '--child-frame-id', 'cam'])
    monitor = launch(argv=['ros2', 'run', 'tf2_ros', 'tf2_monitor', 'world', 'cam'])
    monitor.wait_for_output(r'^Gathering data on world -> cam for 10 seconds\.\.\.$', timeout=20)
    monitor.wait_for_output(r'^RESULTS: for world to cam\nChain is: world -> cam\n'
                            r'Net delay     avg = [-\de.+]+: max = [-\de.+]+\n\nFrames:\n'
                            r'Frame: cam, published by <no authority available>, '
                            r'Average Delay: [-\de.+]+, Max Delay: [-\de.+]+\n', timeout=30)
    assert monitor.stop() == 0


def test_bad_transforms_on_tf_are_refused_and_the_listener_goes_on(launch, probe) -> None:
    """NaN, a non-unit quaternion, a self-transform and a missing child id, sent on /tf to a
    running tf2_echo: one error line each in tf2's words, then a good transform is echoed."""
    from geometry_msgs.msg import TransformStamped
    from tf2_msgs.msg import TFMessage

    echo = launch(argv=['ros2', 'run', 'tf2_ros', 'tf2_echo', 'world', 'robot'])
    publisher = probe.node.create_publisher(TFMessage, '/tf', 100)
    probe.spin_until(lambda: publisher.get_subscription_count() >= 1, 20, 'the echo on /tf')

    def transform(parent: str, child: str, x: float = 1.0, qw: float = 1.0) -> TransformStamped:
        t = TransformStamped()
        t.header.stamp = probe.node.get_clock().now().to_msg()
        t.header.frame_id, t.child_frame_id = parent, child
        t.transform.translation.x, t.transform.rotation.w = x, qw
        return t

    publisher.publish(TFMessage(transforms=[
        transform('world', 'robot', x=float('nan')), transform('world', 'robot', qw=2.0),
        transform('world', 'world'), transform('world', '')]))
    for pattern in (r'TF_NAN_INPUT: Ignoring transform for child_frame_id "robot" from '
                    r'authority "[^"]*" because of a nan value in the transform \(nan 0\.000000 '
                    r'0\.000000\) \(0\.000000 0\.000000 0\.000000 1\.000000\)',
                    r'TF_DENORMALIZED_QUATERNION: Ignoring transform for child_frame_id "robot" '
                    r'from authority "[^"]*" because of an invalid quaternion in the transform '
                    r'\(0\.000000 0\.000000 0\.000000 2\.000000\)',
                    r'TF_SELF_TRANSFORM: Ignoring transform from authority "[^"]*" with '
                    r'frame_id and  child_frame_id "world" because they are the same',
                    r'TF_NO_CHILD_FRAME_ID: Ignoring transform from authority "[^"]*" because '
                    r'child_frame_id not set'):
        echo.wait_for_output(r'^\[ERROR\] \[[\d.]+\] \[\]: ' + pattern, timeout=20)
    deadline = time.monotonic() + 20
    while 'Translation: [1.000, 0.000, 0.000]' not in echo.output:
        assert time.monotonic() < deadline, echo.output
        publisher.publish(TFMessage(transforms=[transform('world', 'robot')]))
        probe.spin_for(0.2)
    assert 'nan' not in echo.output.split('At time')[-1]
    assert echo.stop() == 0
    assert 'Traceback' not in echo.output
