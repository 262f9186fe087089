"""launch_testing's class fixtures, launch arguments and tools, and launch_testing_ros's
DataRepublisher, as upstream's tests (and ros2cli's, which start `ros2 ...` mid-test) use them.

The example launch tests live in tests/data/launch_testing (example_*.py: pytest does not
collect them itself); they run through `launch_test` and through pytest's plugin.
"""
from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

from launch_testing.tools import basic_output_filter, expect_output
from launch_testing.tools.text import build_line_match
from launch_testing_ros import DataRepublisher
from launch_testing_ros.tools import basic_output_filter as ros_output_filter
from std_msgs.msg import String

EXAMPLES = Path(__file__).parent / 'data' / 'launch_testing'


def run(env: dict[str, str], *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(list(args), env=env, capture_output=True, text=True, timeout=120,
                          stdin=subprocess.DEVNULL)


def test_each_class_fixture_runs_once_and_tests_see_the_launch_arguments(ros_env) -> None:
    # unittest remembers the last test class on the result: the active tests' tearDownClass
    # ran again when the post-shutdown tests started (an rclpy.shutdown() there then failed).
    result = run(ros_env, 'launch_test', str(EXAMPLES / 'example_fixtures_launch.py'),
                 'who:=world')
    assert result.returncode == 0, result.stdout + result.stderr
    fixtures = re.findall(r'^fixture: (.*)$', result.stdout, re.MULTILINE)
    assert fixtures == ['active setUpClass', 'active tearDownClass',
                        'post-shutdown setUpClass', 'post-shutdown tearDownClass'], \
        result.stdout
    assert 'test_greets_the_launch_argument (example_fixtures_launch.TestWhileRunning) ... ok' \
        in result.stderr


def test_pytest_plugin_takes_launch_args(ros_env, tmp_path) -> None:
    # upstream's pytest.ini passes `--launch-args dut_arg:=test`; it used to be refused.
    result = run(ros_env, sys.executable, '-m', 'pytest', '-p', 'no:cacheprovider',
                 '--rootdir', str(tmp_path), str(EXAMPLES / 'example_fixtures_launch.py'),
                 '--launch-args', 'who:=pytest')
    assert result.returncode == 0, result.stdout + result.stderr
    assert '1 passed' in result.stdout


def test_output_tools_match_text_and_lines() -> None:
    output = 'pid 42\n[talker] I said: foo\n[listener] I heard: foo\nrc 0\n'
    filtered = basic_output_filter()(output)
    assert filtered == '[talker] I said: foo\n[listener] I heard: foo\n'
    assert basic_output_filter(filtered_patterns=[r'.*\[listener\]'])(filtered) == \
        '[talker] I said: foo\n'
    assert ros_output_filter(filtered_prefixes=['[talker]'],
                             filtered_rmw_implementation='rmw_fastrtps_cpp')(filtered) == \
        '[listener] I heard: foo\n'
    lines = filtered.splitlines()
    assert expect_output(expected_lines=lines, text=filtered, strict=True)
    assert expect_output(expected_text=filtered, lines=lines)
    assert not expect_output(expected_lines=[lines[1], lines[0]], lines=lines)  # order
    assert not expect_output(expected_lines=[re.compile(r'\[listener\]')], lines=lines,
                             strict=True)  # strict: every line must match
    assert expect_output(expected_text=re.compile(r'said: \w+$', re.M),
                         text='\x1b[32m[talker] I said: foo\x1b[0m')
    assert build_line_match(['I said', 'I heard'])(lines) == (0, 2)


def test_data_republisher_transforms_and_drops(probe) -> None:
    node = probe.node
    republisher = DataRepublisher(node, 'lrt_in', 'lrt_out', String,
                                  lambda msg: None if msg.data == 'skip'
                                  else String(data=msg.data.upper()))
    received = probe.collect(String, 'lrt_out')
    publisher = node.create_publisher(String, 'lrt_in', 10)
    probe.spin_until(lambda: publisher.get_subscription_count() > 0
                     and node.count_subscribers('lrt_out') > 0, 10, 'the republisher')
    for word in ('hello', 'skip', 'world'):
        publisher.publish(String(data=word))
    probe.spin_until(lambda: len(received) >= 2, 10, 'two republished messages')
    probe.spin_for(0.2)
    assert [msg.data for msg in received] == ['HELLO', 'WORLD']
    assert republisher.get_num_received() == 3 and republisher.get_num_republished() == 2
    assert [msg.data for msg in republisher.get_republished()] == ['hello', 'world']
    republisher.shutdown()
