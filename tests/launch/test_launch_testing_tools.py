"""launch_testing's class fixtures, launch arguments, tools, runner validation, JUnit XML,
StdoutReadyListener and `--show-args`, and launch_testing_ros's DataRepublisher, as upstream's
tests (and ros2cli's, which start `ros2 ...` mid-test) use them.

The example launch tests live in tests/data/launch_testing (example_*.py: pytest does not
collect them itself); they run through `launch_test` and through pytest's plugin.
"""
from __future__ import annotations

import io
import re
import subprocess
import sys
import types
import unittest
from pathlib import Path

import pytest
from launch.actions import ExecuteProcess, OpaqueFunction, RegisterEventHandler
from launch_testing.asserts import SequentialTextChecker
from launch_testing.event_handlers import StdoutReadyListener
from launch_testing.junitxml import unittestResultsToXml
from launch_testing.loader import LoadTestsFromPythonModule
from launch_testing.test_result import FailResult, SkipResult
from launch_testing.test_result import TestResult as LaunchTestResult
from launch_testing.test_runner import LaunchTestRunner
from launch_testing.tools import basic_output_filter, expect_output
from launch_testing.tools.text import build_line_match
from launch_testing_ros.tools import basic_output_filter as ros_output_filter
from std_msgs.msg import String

import launch_testing
from launch import LaunchDescription, LaunchService
from launch_testing_ros import DataRepublisher

EXAMPLES = Path(__file__).parents[1] / 'data' / 'launch_testing'


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
    assert expect_output(expected_text=filtered.rstrip('\n'), lines=lines)
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


def runs_of(description, **classes) -> list:
    module = types.ModuleType('lrt_module')
    module.generate_test_description = description
    for name, cls in classes.items():
        cls.__module__ = 'lrt_module'
        setattr(module, name, cls)
    return LoadTestsFromPythonModule(module)


def test_runner_validation_names_bad_description_arguments() -> None:
    def extra(ready_fn, typo):
        return None

    with pytest.raises(Exception, match="unexpected extra argument 'typo'"):
        LaunchTestRunner(runs_of(extra)).validate()

    @launch_testing.parametrize('speed', [1, 2])
    def missing():
        return None

    with pytest.raises(Exception, match=r"Could not find an argument .* 'speed'"):
        LaunchTestRunner(runs_of(missing)).validate()

    @launch_testing.parametrize('speed', [1, 2])
    def good(speed, ready_fn):
        return None

    LaunchTestRunner(runs_of(good)).validate()


def test_sequential_checker_shows_the_lines_around_the_last_match() -> None:
    checker = SequentialTextChecker(['one\n', 'two\n', 'three\n', 'four\nfive\n', 'six\n'])
    checker.assertInStdout('two')
    with pytest.raises(AssertionError) as failure:
        checker.assertInStdout('seven')
    # Up to two lines before the match's line, and the three lines after it.
    assert checker.get_nearby_lines() == 'one\ntwo\nthree\nfour\nfive'
    assert str(failure.value).endswith('one\ntwo\nthree\nfour\nfive')


def test_junit_xml_of_failed_skipped_and_run_tests() -> None:
    class Cases(unittest.TestCase):
        def test_passes(self):
            pass

        def test_fails(self):
            assert 1 == 2

    Cases.__qualname__ = 'Cases'
    runs = runs_of(lambda: None, Cases=Cases)
    ran = unittest.TextTestRunner(stream=io.StringIO(), resultclass=LaunchTestResult).run(
        unittest.TestLoader().loadTestsFromTestCase(Cases))
    root = unittestResultsToXml(name='lrt', test_results={
        'ran': ran, 'launch_failed': FailResult(test_run=runs[0], message='no launch'),
        'skipped': SkipResult(test_run=runs[0], skip_reason='not today')}).getroot()
    assert (root.get('tests'), root.get('failures'), root.get('skipped')) == ('6', '3', '2')
    ran_suite, failed_suite, skipped_suite = root.findall('testsuite')
    failure = ran_suite.find("testcase[@name='test_fails']/failure")
    assert '1 == 2' in failure.get('message')  # the failing line, even for a bare assert
    assert [c.get('classname') for c in ran_suite] == ['lrt_module.Cases'] * 2
    assert {f.get('message') for f in failed_suite.iter('failure')} == {'no launch'}
    assert {s.get('message') for s in skipped_suite.iter('skipped')} == {'not today'}


def test_stdout_ready_listener_runs_its_actions_on_the_ready_line() -> None:
    seen = []
    talker = ExecuteProcess(cmd=[sys.executable, '-u', '-c', 'print("warming up"); '
                                 'print("node is Ready")'])
    other = ExecuteProcess(cmd=[sys.executable, '-u', '-c', 'print("Ready too early")'])

    def listener(target, text, mark):
        return RegisterEventHandler(StdoutReadyListener(
            target_action=target, ready_txt=text,
            actions=[OpaqueFunction(function=lambda _context: seen.append(mark))]))

    service = LaunchService()
    service.include_launch_description(LaunchDescription([
        talker, other, listener(talker, 'Ready', 'talker ready'),
        listener(talker, 'never said', 'wrong text')]))
    assert service.run() == 0
    assert seen == ['talker ready']  # once, for its own process, for its own text


def test_launch_test_show_args(ros_env) -> None:
    listed = run(ros_env, 'launch_test', str(EXAMPLES / 'example_fixtures_launch.py'),
                 '--show-args')
    assert listed.stdout.startswith("Arguments (pass arguments as '<name>:=<value>'):\n\n"
                                    "    'who':\n"), listed.stdout
    none = run(ros_env, 'launch_test', str(EXAMPLES / 'example_talker_launch.py'), '--show-args')
    assert none.returncode == 0 and none.stdout == 'No arguments.\n'


def test_launch_process_starts_a_command_mid_test(ros_env) -> None:
    # As ros2cli's tests start `ros2 ...`: through launch's IncludeLaunchDescription event,
    # emitted from the test's thread, with the output filtered and matched line by line.
    result = run(ros_env, 'launch_test', str(EXAMPLES / 'example_mid_test_process_launch.py'))
    assert result.returncode == 0, result.stdout + result.stderr
    assert 'test_runs_a_command_mid_test (example_mid_test_process_launch.TestMidTest) ... ok' \
        in result.stderr
