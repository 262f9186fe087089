"""add_launch_test() as Jazzy's launch_testing_ament_cmake: a package shaped like the
"Integration testing with launch_testing" page's (the test run through ament_cmake_ros's
run_test_isolated.py as RUNNER, an ENV passed on to ament_add_test) and a plain
`add_launch_test(test/x.py)` both build and pass `colcon test`: test names from the file's
path, LABELS `launch_test` by default, each class fixture run once.
"""
from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

from support import run_checked

EXAMPLES = Path(__file__).parents[1] / 'data' / 'launch_testing'

CMAKE_TESTS = """if(BUILD_TESTING)
  find_package(ament_cmake_ros REQUIRED)
  find_package(launch_testing_ament_cmake REQUIRED)
  function(add_ros_isolated_launch_test path)
    set(RUNNER "${ament_cmake_ros_DIR}/run_test_isolated.py")
    add_launch_test("${path}" RUNNER "${RUNNER}" ${ARGN})
  endfunction()
  add_ros_isolated_launch_test(test/test_integration.py ENV FIXTURE_LOG=@LOG@)
  add_launch_test(test/x.py)
"""
DEPENDS = ('ament_cmake_ros', 'launch', 'launch_ros', 'launch_testing',
           'launch_testing_ament_cmake', 'rclpy', 'turtlesim')


def test_add_launch_test_like_the_integration_page_and_plain(tmp_path, ros_env) -> None:
    src = tmp_path / 'src'
    src.mkdir()
    run_checked(['ros2', 'pkg', 'create', '--build-type', 'ament_cmake', '--license',
                 'Apache-2.0', 'app'], src, ros_env)
    package = src / 'app'
    (package / 'test').mkdir()
    shutil.copy(EXAMPLES / 'example_integration_page.py', package / 'test' / 'test_integration.py')
    shutil.copy(EXAMPLES / 'example_talker_launch.py', package / 'test' / 'x.py')
    shutil.copy(EXAMPLES / 'talker.py', package / 'test')
    log = tmp_path / 'fixtures.log'
    cmake = (package / 'CMakeLists.txt').read_text()
    (package / 'CMakeLists.txt').write_text(cmake.replace(
        'if(BUILD_TESTING)\n', CMAKE_TESTS.replace('@LOG@', str(log)), 1))
    xml = (package / 'package.xml').read_text()
    (package / 'package.xml').write_text(xml.replace('  <test_depend>', ''.join(
        f'  <test_depend>{name}</test_depend>\n' for name in DEPENDS) + '  <test_depend>', 1))

    run_checked(['colcon', 'build'], tmp_path, ros_env, timeout=300)
    listed = subprocess.run(['ctest', '-N', '-L', 'launch_test'], cwd=tmp_path / 'build' / 'app',
                            env=ros_env, capture_output=True, text=True, timeout=60)
    assert 'Test #1: test_test_integration.py\n' in listed.stdout, listed.stdout
    assert 'Test #2: test_x.py\n' in listed.stdout, listed.stdout
    tested = subprocess.run(['colcon', 'test', '--ctest-args', '-L', 'launch_test'],
                            cwd=tmp_path, env=ros_env, capture_output=True, text=True,
                            timeout=300)
    assert tested.returncode == 0, tested.stdout + tested.stderr
    result = subprocess.run(['colcon', 'test-result', '--all', '--verbose'], cwd=tmp_path,
                            env=ros_env, capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stdout
    assert 'test_test_integration.py.xunit.xml: 3 tests, 0 errors, 0 failures, 0 skipped' \
        in result.stdout, result.stdout
    assert 'test_x.py.xunit.xml: 2 tests, 0 errors, 0 failures, 0 skipped' in result.stdout
    assert log.read_text() == 'setUpClass\ntearDownClass\n'
