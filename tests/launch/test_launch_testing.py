"""launch_testing, launch_testing_ros and launch_testing_ament_cmake with upstream's API.

The example launch tests in tests/data/launch_testing (named example_*.py, so that pytest
itself does not collect them) run through the `launch_test` command,
then as `colcon test` runs them: in an ament_python package (the pytest plugin) and in an
ament_cmake package (add_launch_test), each with a test that must fail; colcon test-result
names the failing test file and line.
"""
from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

from support import run_checked

EXAMPLES = Path(__file__).parents[1] / 'data' / 'launch_testing'


def launch_test(env: dict[str, str], name: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(['launch_test', str(EXAMPLES / name)], env=env, capture_output=True,
                          text=True, timeout=120, stdin=subprocess.DEVNULL)


def test_launch_test_command(ros_env) -> None:
    passing = launch_test(ros_env, 'example_talker_launch.py')
    assert passing.returncode == 0, passing.stderr
    assert passing.stderr.endswith(
        'test_talks (example_talker_launch.TestTalker) ... ok\n'
        'test_exit_code (example_talker_launch.TestTalkerShutdown) ... ok\n\n' + '-' * 70 + '\n'
        'Ran 2 tests in ' + passing.stderr.split('Ran 2 tests in ')[1].split('s\n')[0]
        + 's\n\nOK\n'), passing.stderr
    assert '[python-1] Hello World: 2' in passing.stdout + passing.stderr

    exit_code = launch_test(ros_env, 'example_failing_exit_launch.py')
    assert exit_code.returncode == 1
    assert re.search(
        r'FAIL: test_exit_code \(example_failing_exit_launch\.TestExitCodes\.test_exit_code\)\n'
        r'-+\nTraceback \(most recent call last\):\n'
        r'  File ".*/example_failing_exit_launch\.py", line \d+, in test_exit_code\n'
        r'    launch_testing\.asserts\.assertExitCodes\(proc_info\)\n'
        r'AssertionError: Proc python-1 exited with code 3 \(allowed: 0; cmd: ',
        exit_code.stderr), exit_code.stderr

    timed_out = launch_test(ros_env, 'example_failing_wait_launch.py')
    assert timed_out.returncode == 1
    assert re.search(
        r'  File ".*/example_failing_wait_launch\.py", line \d+, in test_says_goodbye\n.*\n'
        r"AssertionError: Waiting for output timed out\n  expected 'Goodbye' on stdout of any "
        r'process within 2 s\n  last stdout of python-1:\n    Hello World: 0\n'
        r'    Hello World: 1\n', timed_out.stderr), timed_out.stderr


def test_ros_launch_test_with_wait_for_topics(ros_env) -> None:
    turtlesim = launch_test(ros_env, 'example_turtlesim_launch.py')
    assert turtlesim.returncode == 0, turtlesim.stdout + turtlesim.stderr
    assert 'test_pose_is_published (example_turtlesim_launch.TestTurtlesim) ... ok' in \
        turtlesim.stderr


def test_colcon_test_runs_launch_tests_and_reports_failures(tmp_path, ros_env) -> None:
    src = tmp_path / 'src'
    src.mkdir()
    run_checked(['ros2', 'pkg', 'create', '--build-type', 'ament_python', '--license',
                 'Apache-2.0', 'launch_demo_py'], src, ros_env)
    run_checked(['ros2', 'pkg', 'create', '--build-type', 'ament_cmake', '--license',
                 'Apache-2.0', 'launch_demo_cmake'], src, ros_env)
    python_tests = src / 'launch_demo_py' / 'test'
    shutil.copy(EXAMPLES / 'talker.py', python_tests)
    shutil.copy(EXAMPLES / 'example_talker_launch.py', python_tests / 'test_talker_launch.py')
    shutil.copy(EXAMPLES / 'example_failing_wait_launch.py',
                python_tests / 'test_goodbye_launch.py')
    cmake_package = src / 'launch_demo_cmake'
    (cmake_package / 'test').mkdir()
    shutil.copy(EXAMPLES / 'talker.py', cmake_package / 'test')
    for example, name in (('example_talker_launch.py', 'talker_launch_test.py'),
                          ('example_failing_exit_launch.py', 'failing_exit_launch_test.py')):
        shutil.copy(EXAMPLES / example, cmake_package / 'test' / name)
    cmake = (cmake_package / 'CMakeLists.txt').read_text()
    (cmake_package / 'CMakeLists.txt').write_text(cmake.replace(
        'if(BUILD_TESTING)\n', 'if(BUILD_TESTING)\n'
        '  find_package(launch_testing_ament_cmake REQUIRED)\n'
        '  add_launch_test(test/talker_launch_test.py)\n'
        '  add_launch_test(test/failing_exit_launch_test.py)\n', 1))
    xml = (cmake_package / 'package.xml').read_text()
    (cmake_package / 'package.xml').write_text(xml.replace(
        '  <test_depend>', '  <test_depend>launch_testing_ament_cmake</test_depend>\n'
        '  <test_depend>', 1))
    run_checked(['colcon', 'build', '--symlink-install'], tmp_path, ros_env, timeout=300)
    tested = subprocess.run(
        ['colcon', 'test', '--pytest-args', '-k', 'launch', '--ctest-args', '-R', 'launch_test'],
        cwd=tmp_path, env=ros_env, capture_output=True, text=True, timeout=300)
    assert tested.returncode == 0, tested.stdout + tested.stderr  # colcon test itself ran
    result = subprocess.run(['colcon', 'test-result', '--all', '--verbose'], cwd=tmp_path,
                            env=ros_env, capture_output=True, text=True, timeout=60)
    report = result.stdout
    assert result.returncode == 1, report
    assert 'talker_launch_test.py.xunit.xml: 2 tests, 0 errors, 0 failures, 0 skipped' \
        in report, report
    assert 'failing_exit_launch_test.py.xunit.xml: 2 tests, 0 errors, 1 failure, 0 skipped' \
        in report
    assert 'launch_demo_py/pytest.xml: 2 tests, 0 errors, 1 failure, 0 skipped' in report
    # Each failure names the test and the file and line of the failing assertion.
    assert re.search(r'failing_exit_launch_test\.py", line \d+, in test_exit_code', report), \
        report
    assert re.search(r'AssertionError: Proc python3?-1 exited with code 3', report), report
    assert re.search(r'FAILURE: test_says_goodbye \(test_goodbye_launch\.TestTalker\) at '
                     r'\S+/test_goodbye_launch\.py:\d+: AssertionError: Waiting for output '
                     r'timed out', report), report
