"""`ros2 pkg create` -> `colcon build` -> `colcon test` -> `ros2 run`, in a workspace on ours.

Two packages as the Client-libraries tutorials make them: an ament_python package with a node
(its generated flake8/pep257 tests run for real, the copyright test is skipped as generated),
and an ament_cmake interfaces package with the tutorial's CMake and package.xml additions,
whose ament_lint_auto tests (lint_cmake, xmllint) run through this workspace's ament_lint
packages. It holds only the tutorial's Num.msg: each further interface costs ~10-20 s of
build on this machine (the tutorial's Sphere.msg/AddThreeInts.srv build the same way).
"""

from __future__ import annotations

import os
import re
import subprocess
from pathlib import Path

import pytest

from ws_testing import run_checked as run

CMAKE_INTERFACES = '''\
find_package(geometry_msgs REQUIRED)
find_package(rosidl_default_generators REQUIRED)

rosidl_generate_interfaces(${PROJECT_NAME}
  "msg/Num.msg"
  DEPENDENCIES geometry_msgs # Add packages that above messages depend on, in this case \
geometry_msgs for Sphere.msg
)
'''
XML_INTERFACES = '''\
  <depend>geometry_msgs</depend>
  <buildtool_depend>rosidl_default_generators</buildtool_depend>
  <exec_depend>rosidl_default_runtime</exec_depend>
  <member_of_group>rosidl_interface_packages</member_of_group>

'''


def sourced(workspace: Path, env: dict[str, str], command: str) -> list[str]:
    """`source install/setup.bash && <command>` in bash, as the tutorial does."""
    return ['bash', '-c', f'source {workspace}/install/setup.bash && {command}']


@pytest.fixture(scope='module')
def workspace(tmp_path_factory) -> Path:
    """The two created packages, edited as the tutorials say, built with colcon."""
    from ws_testing import leased_domain, ros_environment
    root = tmp_path_factory.mktemp('ros2_ws')
    src = root / 'src'
    src.mkdir()
    with leased_domain() as domain:
        env = ros_environment(domain)
        run(['ros2', 'pkg', 'create', '--build-type', 'ament_python', '--license', 'Apache-2.0',
             '--node-name', 'my_node', 'my_package', '--dependencies', 'rclpy', 'std_msgs'],
            src, env)
        run(['ros2', 'pkg', 'create', '--build-type', 'ament_cmake', '--license', 'Apache-2.0',
             'tutorial_interfaces'], src, env)
    interfaces = src / 'tutorial_interfaces'
    (interfaces / 'msg').mkdir()
    (interfaces / 'msg/Num.msg').write_text('int64 num\n')
    cmake = (interfaces / 'CMakeLists.txt').read_text()
    (interfaces / 'CMakeLists.txt').write_text(cmake.replace(
        '\nif(BUILD_TESTING)', '\n' + CMAKE_INTERFACES + '\nif(BUILD_TESTING)'))
    xml = (interfaces / 'package.xml').read_text()
    (interfaces / 'package.xml').write_text(xml.replace('  <test_depend>ament_lint_auto',
                                                        XML_INTERFACES + '  <test_depend>'
                                                        'ament_lint_auto'))
    build = run(['colcon', 'build', '--symlink-install'], root, env)
    assert 'Summary: 2 packages finished' in build.stdout, build.stdout
    return root


def test_build_test_and_run_created_packages(workspace, ros_env):
    tested = run(['colcon', 'test', '--event-handlers', 'console_direct+'], workspace, ros_env)
    results = run(['colcon', 'test-result', '--all', '--verbose'], workspace, ros_env)
    summary = re.search(r'Summary: (\d+) tests, (\d+) errors, (\d+) failures, (\d+) skipped',
                        results.stdout)
    assert summary, results.stdout
    tests, errors, failures, skipped = map(int, summary.groups())
    assert (errors, failures) == (0, 0), results.stdout + tested.stdout
    # ament_python: copyright (skipped as generated), flake8, pep257; ament_cmake: lint_cmake
    # and xmllint (copyright and cpplint switched off by the generated CMakeLists.txt).
    assert (tests, skipped) == (7, 1), results.stdout  # ctest counts lint tests twice
    out = tested.stdout
    assert re.search(r'test/test_flake8\.py \.', out) and re.search(r'test_pep257\.py \.', out)
    assert 'lint_cmake' in out and 'xmllint' in out, out
    assert "File 'package.xml' is valid" in out, out

    hello = run(sourced(workspace, ros_env, 'ros2 run my_package my_node'), workspace, ros_env,
                timeout=30)
    assert hello.stdout == 'Hi from my_package.\n'
    shown = run(sourced(workspace, ros_env, 'ros2 interface show tutorial_interfaces/msg/Num'),
                workspace, ros_env, timeout=30)
    assert shown.stdout == 'int64 num\n'
    used = run(sourced(workspace, ros_env, "python3 -c 'from tutorial_interfaces.msg import Num; "
                                           "print(Num(num=7))'"), workspace, ros_env, timeout=30)
    assert used.stdout == 'tutorial_interfaces.msg.Num(num=7)\n'


def test_a_lint_error_fails_colcon_test(workspace, ros_env):
    """The linters really run: style errors in the created packages fail their tests."""
    node = workspace / 'src/my_package/my_package/my_node.py'
    cmake = workspace / 'src/tutorial_interfaces/CMakeLists.txt'
    originals = {path: path.read_text() for path in (node, cmake)}
    node.write_text(originals[node] + 'unused = 1;\n')
    # ctest runs the linters on the sources: no rebuild needed to see this line.
    cmake.write_text(originals[cmake] + 'message(STATUS "x" )\n')
    try:
        subprocess.run(['colcon', 'test'], cwd=workspace, env=ros_env, capture_output=True,
                       text=True, timeout=240)
        results = subprocess.run(['colcon', 'test-result', '--verbose'], cwd=workspace,
                                 env=ros_env, capture_output=True, text=True, timeout=60)
        assert results.returncode != 0
        assert 'E703 statement ends with a semicolon' in results.stdout, results.stdout
        assert 'CMakeLists.txt:' in results.stdout and '[whitespace/mismatch]' in \
            results.stdout, results.stdout
    finally:
        for path, text in originals.items():
            path.write_text(text)


@pytest.mark.skipif(os.geteuid() != 0, reason='needs root for a mount namespace')
def test_missing_linter_programs_are_reported_as_skipped(tmp_path, ros_env):
    """Without the cppcheck/uncrustify programs, a C++ package's lint tests say so, skipped.

    The programs are hidden inside a private mount namespace (if this machine has them).
    """
    src = tmp_path / 'src'
    src.mkdir()
    run(['ros2', 'pkg', 'create', '--build-type', 'ament_cmake', '--license', 'Apache-2.0',
         '--node-name', 'my_node', 'my_cpp'], src, ros_env)
    hide = ''.join(f'[ -e {path} ] && mount --bind /dev/null {path}; '
                   for path in ('/usr/bin/cppcheck', '/usr/bin/uncrustify'))
    built = run(['unshare', '-m', 'bash', '-c',
                 hide + 'colcon build && colcon test && colcon test-result --all'],
                tmp_path, ros_env, timeout=240)
    out = built.stdout
    assert re.search(r"my_cpp/cppcheck\.xunit\.xml: 1 test, 0 errors, 0 failures, 1 skipped",
                     out), out
    assert re.search(r"my_cpp/uncrustify\.xunit\.xml: 1 test, 0 errors, 0 failures, "
                     r"1 skipped", out), out
    reason = (tmp_path / 'build/my_cpp/test_results/my_cpp/uncrustify.xunit.xml').read_text()
    assert "message=\"the 'uncrustify' program is not installed (apt-get install " \
        'uncrustify)"' in reason
    hello = run(['bash', '-c', f'source {tmp_path}/install/setup.bash && ros2 run my_cpp my_node'],
                tmp_path, ros_env, timeout=30)
    assert hello.stdout == 'hello world my_cpp package\n'


def test_writing_basic_tests_with_python(tmp_path, ros_env):
    """"Writing Basic Tests with Python" (Jazzy): the page's package layout, its failing
    test_math in tests/, `colcon test --packages-select ... --pytest-args -k test_math` and
    `colcon test-result --all --verbose` naming the failure."""
    src = tmp_path / 'src'
    src.mkdir()
    run(['ros2', 'pkg', 'create', '--build-type', 'ament_python', '--license', 'Apache-2.0',
         'awesome_ros_package'], src, ros_env)
    package = src / 'awesome_ros_package'
    (package / 'awesome_ros_package' / 'fozzie.py').write_text('"""Fozzie."""\n')
    tests = package / 'tests'
    tests.mkdir()
    (tests / 'test_fozzie.py').write_text(
        'def test_math():\n    assert 2 + 2 == 5   # This should fail for most mathematical '
        'systems\n')
    # The page's one setup.py requirement, which ros2 pkg create already writes.
    assert "tests_require=['pytest']," in (package / 'setup.py').read_text()
    run(['colcon', 'build'], tmp_path, ros_env)
    run(['colcon', 'test', '--packages-select', 'awesome_ros_package', '--pytest-args', '-k',
         'test_math'], tmp_path, ros_env)
    results = subprocess.run(['colcon', 'test-result', '--all', '--verbose'], cwd=tmp_path,
                             env=ros_env, capture_output=True, text=True, timeout=60)
    assert results.returncode == 1
    assert re.search(r'build/awesome_ros_package/pytest\.xml: 1 test, 0 errors, 1 failure',
                     results.stdout), results.stdout
    assert re.search(r'- awesome_ros_package\.tests\.test_fozzie test_math\n'
                     r'  <<< failure message\n    assert \(2 \+ 2\) == 5', results.stdout), \
        results.stdout
