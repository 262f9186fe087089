"""Fuzz turtlesim, turtle_controller and the ros2 CLI with 10,000 generated cases.

The properties are the tests' own (turtlesim's and my_robot_controller's test_fuzz_*.py);
only the number of examples per property differs (FUZZ_MAX_EXAMPLES). Prints the cases run
per property and what failed.
"""

from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
import time

from common import REPO, RESULTS

PROPERTIES = {  # test module -> its number of properties (each case: real DDS round trips)
    'src/turtlesim/test/test_fuzz_turtlesim.py': 7,
    'src/my_robot_controller/test/test_fuzz_controller.py': 1,
}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--cases', type=int, default=10_000, help='total generated cases')
    parser.add_argument('--seed', type=int, default=None,
                        help='random seed (default: a derandomized fixed sequence)')
    args = parser.parse_args()
    # test_fuzz_turtlesim.py holds 7 properties, the controller's module one.
    per_property = max(1, args.cases // sum(PROPERTIES.values()))
    env = dict(os.environ, FUZZ_MAX_EXAMPLES=str(per_property), FUZZ_VERBOSE='1')
    # -s: Hypothesis's verbose report (one 'Test case:' per case) is what is counted;
    # no per-test timeout: 1,250 real round trips per property take minutes.
    command = [sys.executable, '-m', 'pytest', '-q', '-s', '-p', 'no:cacheprovider',
               '--timeout=0', *PROPERTIES]
    if args.seed is not None:
        command.append(f'--hypothesis-seed={args.seed}')
        env['FUZZ_RANDOM'] = '1'
    started = time.monotonic()
    result = subprocess.run(command, cwd=REPO, env=env, capture_output=True, text=True,
                            timeout=3600)
    elapsed = time.monotonic() - started
    RESULTS.mkdir(exist_ok=True)
    (RESULTS / 'logs').mkdir(exist_ok=True)
    (RESULTS / 'logs' / 'fuzz.log').write_text(result.stdout + result.stderr)
    # pytest's progress dot lands in front of each later property's first case.
    cases = len(re.findall(r'^\.*Test case: ', result.stdout, re.MULTILINE))
    summary = result.stdout.strip().splitlines()[-1] if result.stdout.strip() else ''
    print(f'fuzz: {cases} generated cases in {elapsed:.0f} s ({per_property} per property, '
          f'{len(PROPERTIES)} modules); pytest: {summary}')
    for line in re.findall(r'^(FAILED .*|E +Failing test case.*)$', result.stdout, re.MULTILINE):
        print(f'  {line}')
    return result.returncode


if __name__ == '__main__':
    sys.exit(main())
