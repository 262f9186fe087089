"""ws_testing's pytest plugin as a pytest run in another folder sees it: its fixtures wherever
ws_testing is installed, the leak check only where the ini option ws_testing_checks is on."""

import re
import subprocess
import sys
from pathlib import Path

LEAVES_A_PROCESS = '''
import os
import subprocess


def test_starts_a_process_and_leaves_it(ros_env):
    assert ros_env['ROS_AUTOMATIC_DISCOVERY_RANGE'] == 'LOCALHOST'
    print('owner:', os.environ.get('TURTLE_WS_TEST_OWNER'))
    subprocess.Popen(['sleep', '{seconds}'], env=ros_env)
'''


def run_pytest(folder: Path, checks: bool, seconds: float) -> subprocess.CompletedProcess[str]:
    (folder / 'pytest.ini').write_text(f'[pytest]\nws_testing_checks = {str(checks).lower()}\n')
    (folder / 'test_leaves_a_process.py').write_text(LEAVES_A_PROCESS.format(seconds=seconds))
    return subprocess.run([sys.executable, '-m', 'pytest', '-q', '-s', '-p', 'no:cacheprovider'],
                          cwd=folder, capture_output=True, text=True, timeout=120)


def test_the_leak_check_fails_the_test_and_kills_what_it_left(tmp_path):
    result = run_pytest(tmp_path, checks=True, seconds=60)
    assert result.returncode == 1, result.stdout + result.stderr
    assert re.search(r'test_leaves_a_process\.py::test_starts_a_process_and_leaves_it left '
                     r'processes running \(killed now\):\npid \d+: sleep 60\n', result.stdout), \
        result.stdout
    assert '1 passed, 1 error' in result.stdout, result.stdout
    # Its processes were marked as the inner test's (the inner session's pid and test id).
    assert re.search(r'^owner: \d+ test_leaves_a_process\.py::test_starts_a_process_and_leaves_it$',
                     result.stdout, re.MULTILINE), result.stdout


def test_without_the_ini_option_the_fixtures_serve_and_nothing_is_checked(tmp_path):
    # The process ends within the outer leak check's grace (this test's own check).
    result = run_pytest(tmp_path, checks=False, seconds=0.5)
    assert result.returncode == 0, result.stdout + result.stderr
    assert 'left processes running' not in result.stdout
    # Nothing marked the inner test's processes: they carry the outer test's mark.
    assert re.search(r'^owner: \d+ \S+test_ws_testing_plugin\.py::test_without_the_ini_option',
                     result.stdout, re.MULTILINE), result.stdout
    assert '1 passed' in result.stdout, result.stdout
