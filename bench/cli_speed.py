"""`ros2` as a learner types it: median wall time of each command, ours next to a reference.

With turtlesim up (`ros2 run turtlesim turtlesim_node --headless`), each command a learner
types (node/topic/service/param/action/interface verbs, plus the first `ros2 node list` after
`ros2 daemon stop`, daemon start included) runs once as a warm-up and then RUNS times; the
median wall time is reported. The daemon already runs where the verb uses it.

Then the overlay case: the one-shot verbs (those the daemon runs for the CLI) in a shell
that has sourced an overlay after the daemon started, i.e. whose AMENT_PREFIX_PATH and
PYTHONPATH start with another prefix (a scratch overlay with one package marker). Its first
call is reported on its own row (our daemon then starts the worker for that environment);
then, once the worker answers, each verb's median as above.

`--reference-ros2 PATH` names another `ros2` to run the same commands with, on the same
domain (e.g. upstream ros2cli on the same rclpy): either its `ros2` executable or the prefix
it is installed in. When the executable lives in `<prefix>/bin`, `<prefix>/bin`, its
`lib/pythonX.Y/site-packages` and `<prefix>` go first on PATH, PYTHONPATH and
AMENT_PREFIX_PATH. Ours and the reference run alternately, so that load hits both alike. The
two daemons cannot collide: ours listens on a Unix socket, upstream's on TCP port
11511 + ROS_DOMAIN_ID on localhost. The reference's daemon is stopped at the end with the
reference's own `ros2 daemon stop`.

Run alone: `scripts/ws python bench/cli_speed.py [--reference-ros2 PATH] [--runs N]`.
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from pathlib import Path

from ament_index_python.packages import get_package_prefix

from common import Row, Session, TestNode, session, verdict

RUNS = 5
TIMEOUT_S = 30.0
TARGET_RATIO = 0.5
COLD_TARGET_MS = 1000
RUN_OWN_PART = "ros2 run turtlesim no_such_executable (the command's own part of `ros2 run`)"
READY_TIMEOUT_S = 30.0
COLD = 'ros2 node list (after ros2 daemon stop; daemon start included)'
SEND_GOAL = ('ros2 action send_goal /turtle1/rotate_absolute turtlesim/action/RotateAbsolute '
             '"{theta: 1.0}" (turns 2 rad)')
SEND_GOAL_SHORT = ('ros2 action send_goal /turtle1/rotate_absolute '
                   'turtlesim/action/RotateAbsolute "{theta: 1.1}" (turns 0.1 rad)')

PUB_ONCE = ('ros2 topic pub --once /turtle1/cmd_vel geometry_msgs/msg/Twist '
            '"{linear: {x: 0.1}}"')
# (shown as, argv after `ros2`, output varies from call to call)
COMMANDS: list[tuple[str, list[str], bool]] = [
    ('ros2 node list', ['node', 'list'], False),
    ('ros2 node info /turtlesim', ['node', 'info', '/turtlesim'], False),
    ('ros2 topic list', ['topic', 'list'], False),
    ('ros2 topic info /turtle1/pose', ['topic', 'info', '/turtle1/pose'], False),
    ('ros2 topic type /turtle1/pose', ['topic', 'type', '/turtle1/pose'], False),
    ('ros2 service list', ['service', 'list'], False),
    ('ros2 service type /clear', ['service', 'type', '/clear'], False),
    ('ros2 param list /turtlesim', ['param', 'list', '/turtlesim'], False),
    ('ros2 param get /turtlesim background_r', ['param', 'get', '/turtlesim', 'background_r'],
     False),
    ('ros2 param set /turtlesim background_r 100',
     ['param', 'set', '/turtlesim', 'background_r', '100'], False),
    ('ros2 topic echo --once /turtle1/pose', ['topic', 'echo', '--once', '/turtle1/pose'], True),
    (PUB_ONCE, ['topic', 'pub', '--once', '/turtle1/cmd_vel', 'geometry_msgs/msg/Twist',
                '{linear: {x: 0.1}}'], True),
    ('ros2 service call /clear std_srvs/srv/Empty',
     ['service', 'call', '/clear', 'std_srvs/srv/Empty'], True),
    ('ros2 action list', ['action', 'list'], False),
    # The goal's theta alternates between calls (see _argv) so that the turtle always turns:
    # by 2 rad, which takes the turtle 2 s at 1 rad/s in both runs, and by 0.1 rad (0.1 s),
    # where the command's own time shows.
    (SEND_GOAL,
     ['action', 'send_goal', '/turtle1/rotate_absolute', 'turtlesim/action/RotateAbsolute',
      '{theta: 1.0}'], True),
    (SEND_GOAL_SHORT,
     ['action', 'send_goal', '/turtle1/rotate_absolute', 'turtlesim/action/RotateAbsolute',
      '{theta: 1.1}'], True),
    ('ros2 interface show turtlesim/srv/Spawn', ['interface', 'show', 'turtlesim/srv/Spawn'],
     False),
    # `ros2 run`'s own part: finding the package and its executable (here, that it has none
    # of that name); the started node's own start-up is the same program for both.
    (RUN_OWN_PART, ['run', 'turtlesim', 'no_such_executable'], False),
]
# The verbs the daemon runs for the CLI (one exchange with the graph each), in the overlay.
ONE_SHOT = ('ros2 param list /turtlesim', 'ros2 param get /turtlesim background_r',
            'ros2 param set /turtlesim background_r 100', 'ros2 topic echo --once /turtle1/pose',
            PUB_ONCE, 'ros2 service call /clear std_srvs/srv/Empty', SEND_GOAL_SHORT)
OVERLAY = ' [overlay sourced after the daemon started]'
OVERLAY_FIRST = ('ros2 param get /turtlesim background_r, first call after sourcing the '
                 'overlay (worker start)')
WORKER_BOUND_S = 30.0
THETAS = {SEND_GOAL: ('{theta: 1.0}', '{theta: -1.0}'),
          SEND_GOAL_SHORT: ('{theta: 1.0}', '{theta: 1.1}')}
# Started, then timed until a probe that already knows the graph discovers every node it
# starts; then Ctrl-C. A second turtlesim under its own name runs next to the first.
RUN = ('ros2 run turtlesim turtlesim_node (until the probe discovers it)',
       ['run', 'turtlesim', 'turtlesim_node', '--headless', '--ros-args', '-r',
        '__node:=timed_turtlesim'], {'/timed_turtlesim'})
LAUNCH = ('ros2 launch turtlesim multisim.launch.py (until the probe discovers both nodes)',
          ['launch', 'turtlesim', 'multisim.launch.py'],
          {'/turtlesim1/turtlesim', '/turtlesim2/turtlesim'})
STARTS = (RUN, LAUNCH)


@dataclass
class Cli:
    """One `ros2` to measure: its executable and the environment it runs in."""

    label: str
    argv0: str
    env: dict[str, str]
    samples: dict[str, list[float]] = field(default_factory=dict)
    outputs: dict[str, str] = field(default_factory=dict)
    failures: dict[str, list[str]] = field(default_factory=dict)
    _verbs: set[str] | None = None

    overlay_env: dict[str, str] | None = None

    def run(self, args: list[str], overlay: bool = False
            ) -> tuple[float, subprocess.CompletedProcess | None]:
        start = time.monotonic()
        env = self.overlay_env if overlay else self.env
        try:
            result = subprocess.run([self.argv0, *args], env=env, capture_output=True,
                                    text=True, timeout=TIMEOUT_S, stdin=subprocess.DEVNULL)
        except subprocess.TimeoutExpired:
            return time.monotonic() - start, None
        return time.monotonic() - start, result

    def measure(self, name: str, args: list[str], keep: bool, overlay: bool = False) -> None:
        elapsed, result = self.run(args, overlay)
        if not keep:
            return
        self.samples.setdefault(name, []).append(elapsed)
        if result is None:
            self.failures.setdefault(name, []).append(f'timed out after {TIMEOUT_S:.0f} s')
            return
        self.outputs[name] = result.stdout
        if result.returncode != 0 and name != RUN_OWN_PART:
            self.failures.setdefault(name, []).append(
                f'exit {result.returncode}: {(result.stderr or result.stdout).strip()[-300:]}')

    def verbs(self) -> set[str]:
        """The verbs this `ros2` has (upstream's `launch` comes with launch_ros, not ros2cli)."""
        if self._verbs is None:
            _, result = self.run(['--help'])
            text = result.stdout if result is not None else ''
            self._verbs = set(re.findall(r'^\s+(\w+)\s{2,}\S', text, re.MULTILINE))
        return self._verbs

    def median_ms(self, name: str) -> float | None:
        values = self.samples.get(name)
        return statistics.median(values) * 1000 if values else None


def _ours(env: dict[str, str]) -> Cli:
    return Cli('ours', str(Path(get_package_prefix('ros2cli')) / 'bin' / 'ros2'), env)


def reference_cli(path: str, env: dict[str, str]) -> Cli:
    """The reference `ros2`: an executable, or a prefix with bin/ros2 in it."""
    given = Path(path).expanduser().resolve()
    argv0 = given / 'bin' / 'ros2' if given.is_dir() else given
    if not os.access(argv0, os.X_OK):
        raise SystemExit(f'cli_speed: no executable ros2 at {argv0}')
    env = dict(env)
    prefix = argv0.parent.parent
    if argv0.parent.name == 'bin':
        sites = sorted(prefix.glob('lib/python3*/site-packages'))
        if sites:
            def first(var: str, value: Path) -> None:
                env[var] = os.pathsep.join([str(value), *filter(None, [env.get(var, '')])])
            first('PATH', argv0.parent)
            first('PYTHONPATH', sites[-1])
            first('AMENT_PREFIX_PATH', prefix)
    return Cli('reference', str(argv0), env)


def _argv(name: str, args: list[str], counter: list[int]) -> list[str]:
    if name not in THETAS:
        return args
    counter[0] += 1
    return [*args[:-1], THETAS[name][counter[0] % len(THETAS[name])]]


def measure_start(cli: Cli, probe: TestNode, name: str, args: list[str], nodes: set[str],
                  keep: bool) -> None:
    """Start `ros2 <args>` and time it until the probe discovers `nodes`; then Ctrl-C it."""
    start = time.monotonic()
    process = subprocess.Popen([cli.argv0, *args], env=cli.env, stdin=subprocess.DEVNULL,
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                               start_new_session=True)
    try:
        probe.spin_until(lambda: nodes <= set(probe.node.get_fully_qualified_node_names())
                         or process.poll() is not None, TIMEOUT_S, ' '.join(args))
        elapsed = time.monotonic() - start
        failed = process.poll() is not None
    except AssertionError:
        elapsed, failed = time.monotonic() - start, True
    finally:
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGINT)
        try:
            _, errors = process.communicate(timeout=TIMEOUT_S)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)
            _, errors = process.communicate()
    # Until every node has left the graph, the next start would be discovered at once.
    try:
        probe.spin_until(lambda: not nodes & set(probe.node.get_fully_qualified_node_names()),
                         TIMEOUT_S, f'the nodes of {" ".join(args)} to leave')
    except AssertionError:
        left = sorted(nodes & set(probe.node.get_fully_qualified_node_names()))
        cli.failures.setdefault(name, []).append(
            f'{", ".join(left)} still listed {TIMEOUT_S:.0f} s after `ros2 {args[0]}` exited '
            f'(exit {process.returncode})')
    if not keep:
        return
    cli.samples.setdefault(name, []).append(elapsed)
    if failed:
        cli.failures.setdefault(name, []).append(
            f'exit {process.returncode}: {errors.decode(errors="replace").strip()[-300:]}')


def make_overlay(directory: Path) -> Path:
    """A scratch overlay prefix as colcon installs one: a package marker and a site dir."""
    prefix = directory / 'install'
    (prefix / 'share' / 'ament_index' / 'resource_index' / 'packages').mkdir(parents=True)
    (prefix / 'share' / 'ament_index' / 'resource_index' / 'packages' / 'bench_overlay').touch()
    version = f'python{sys.version_info[0]}.{sys.version_info[1]}'
    (prefix / 'lib' / version / 'site-packages').mkdir(parents=True)
    return prefix


def sourced(env: dict[str, str], prefix: Path) -> dict[str, str]:
    """`env` after `source <prefix>/setup.bash`: the overlay first on both paths."""
    site = next((prefix / 'lib').glob('python*/site-packages'))
    env = dict(env)
    for var, value in (('AMENT_PREFIX_PATH', prefix), ('PYTHONPATH', site)):
        env[var] = os.pathsep.join([str(value), *filter(None, [env.get(var, '')])])
    return env


def _wait_worker(cli: Cli) -> None:
    """Until our daemon's worker for the overlay's environment answers (started by the first
    overlay call); not for the reference, which has none."""
    if cli.label != 'ours':
        return
    from ros2cli.daemon import client, protocol
    assert cli.overlay_env is not None
    values = {name: cli.overlay_env.get(name, '') for name in protocol.ENVIRONMENT}
    path = protocol.worker_path(protocol.socket_path(cli.overlay_env), values)
    deadline = time.monotonic() + WORKER_BOUND_S
    while not (path.exists() and client.is_running(path)):
        if time.monotonic() > deadline:
            cli.failures.setdefault(OVERLAY_FIRST, []).append(
                f'no worker answered at {path} within {WORKER_BOUND_S:.0f} s')
            return
        time.sleep(0.1)


def measure_overlay(clis: list[Cli], runs: int, counter: list[int]) -> None:
    """The one-shot verbs in a shell that sourced an overlay after the daemon started."""
    directory = Path(tempfile.mkdtemp(prefix='cli_speed_overlay_'))
    try:
        prefix = make_overlay(directory)
        for cli in clis:
            cli.overlay_env = sourced(cli.env, prefix)
            cli.measure(OVERLAY_FIRST, ['param', 'get', '/turtlesim', 'background_r'], True,
                        overlay=True)
        for cli in clis:
            _wait_worker(cli)
        for name, args, _ in COMMANDS:
            if name not in ONE_SHOT:
                continue
            for run in range(runs + 1):
                for cli in clis:
                    cli.measure(name + OVERLAY, _argv(name, args, counter), keep=run > 0,
                                overlay=True)
    finally:
        shutil.rmtree(directory, ignore_errors=True)


def _wait_ready(cli: Cli) -> None:
    """Start the daemon and wait until it lists turtlesim, its services and its action."""
    cli.run(['daemon', 'start'])
    checks = ((['node', 'list'], '/turtlesim'), (['service', 'list'], '/clear'),
              (['topic', 'list'], '/turtle1/pose'),
              (['action', 'list'], '/turtle1/rotate_absolute'))
    deadline = time.monotonic() + READY_TIMEOUT_S
    for args, expected in checks:
        while True:
            _, result = cli.run(args)
            if result is not None and expected in result.stdout.split():
                break
            if time.monotonic() > deadline:
                raise TimeoutError(f'{cli.label} `ros2 {" ".join(args)}` did not list '
                                   f'{expected} within {READY_TIMEOUT_S:.0f} s')
            time.sleep(0.2)


def _masked(text: str) -> str:
    text = re.sub(r'[0-9a-f]{8}-?[0-9a-f]{4}-?[0-9a-f]{4}-?[0-9a-f]{4}-?[0-9a-f]{12}', '<id>',
                  text)
    return re.sub(r'-?\d+(\.\d+)?(e[-+]?\d+)?', '#', text)


def output_differences(ours: Cli, reference: Cli) -> list[str]:
    """The commands whose (last) output differs, numbers masked where they vary by call."""
    notes = []
    for name, _, volatile in COMMANDS:
        a, b = ours.outputs.get(name), reference.outputs.get(name)
        if a is None or b is None:
            continue
        if volatile:
            a, b = _masked(a), _masked(b)
        if a.split() != b.split():
            notes.append(f'{name}:\n  ours:      {a.strip()[:400]!r}\n'
                         f'  reference: {b.strip()[:400]!r}')
    a, b = ours.outputs.get(COLD, ''), reference.outputs.get(COLD, '')
    for cli, text in ((ours, a), (reference, b)):
        if '/turtlesim' not in text.split():
            notes.append(f'{COLD}: {cli.label} did not list /turtlesim '
                         f'in its last cold call ({text.strip()!r})')
    return notes


def measure(s: Session, reference: str | None, runs: int = RUNS) -> list[Cli]:
    turtlesim = s.start_argv([_ours(s.env).argv0, 'run', 'turtlesim', 'turtlesim_node',
                              '--headless'])
    turtlesim.wait_for_output(r'Spawning turtle \[turtle1\]', timeout=30)
    clis = [_ours(s.env)]
    if reference:
        clis.append(reference_cli(reference, s.env))
    counter = [0]
    try:
        for cli in clis:
            cli.run(['daemon', 'stop'])  # a stale daemon of an earlier run on this domain
            _wait_ready(cli)
        for name, args, _ in COMMANDS:
            for run in range(runs + 1):  # run 0 is the warm-up
                for cli in clis:
                    cli.measure(name, _argv(name, args, counter), keep=run > 0)
        measure_overlay(clis, runs, counter)
        probe = s.probe('bench_cli_speed_probe')
        try:
            for name, args, nodes in STARTS:
                for run in range(runs + 1):
                    for cli in clis:
                        if args[0] in cli.verbs():
                            measure_start(cli, probe, name, args, nodes, keep=run > 0)
        finally:
            probe.close()
        for run in range(runs + 1):
            for cli in clis:
                for other in clis:  # after boot: no daemon at all, only turtlesim
                    other.run(['daemon', 'stop'])
                cli.measure(COLD, ['node', 'list'], keep=run > 0)
    finally:
        for cli in clis:
            cli.run(['daemon', 'stop'])
    return clis


def _fmt(value: float | None) -> str:
    return f'{value:.0f}' if value is not None else 'n/a'


def row_names() -> list[str]:
    return ([name for name, _, _ in COMMANDS] + [OVERLAY_FIRST]
            + [name + OVERLAY for name, _, _ in COMMANDS if name in ONE_SHOT]
            + [name for name, _, _ in STARTS] + [COLD])


def table_lines(clis: list[Cli]) -> list[tuple[str, str, str, str, str, str]]:
    ours = clis[0]
    reference = clis[1] if len(clis) > 1 else None
    lines = []
    for name in row_names():
        mine = ours.median_ms(name)
        theirs = reference.median_ms(name) if reference else None
        failed = name in ours.failures
        ratio = mine / theirs if mine is not None and theirs else None
        if name == COLD:  # the bar for the first call is absolute
            target, met = f'<= {COLD_TARGET_MS} ms', mine is not None and mine <= COLD_TARGET_MS
        else:
            target, met = f'<= {TARGET_RATIO}x', ratio is not None and ratio <= TARGET_RATIO
        if theirs is not None:
            theirs_text, ratio_text = _fmt(theirs), f'{ratio:.2f}x' if ratio is not None else 'n/a'
        else:
            theirs_text = 'reference: not given' if reference is None else 'not in the reference'
            ratio_text = ''
        if name == OVERLAY_FIRST:  # the CLI runs it while the worker starts: shown, not judged
            target = 'not judged'
        judged = (theirs is not None or name == COLD) and name != OVERLAY_FIRST
        state = 'FAILED' if failed else verdict(met) if judged else ''
        if reference is not None and name in reference.failures:
            state += ' (reference failed)'
        lines.append((name, _fmt(mine), theirs_text, ratio_text, target, state))
    return lines


def run(s: Session, reference: str | None = None, runs: int = RUNS) -> tuple[list[Row], dict]:
    reference = reference or os.environ.get('CLI_SPEED_REFERENCE_ROS2') or None
    clis = measure(s, reference, runs)
    rows = []
    for name, mine, theirs, ratio, target, state in table_lines(clis):
        value = f'{mine} ms' + (f' (reference {theirs} ms, {ratio})' if ratio else
                                f' ({theirs})')
        rows.append(Row('cli_speed', f'`{name}`, median of {runs}', value, target, state))
    data = {'cli_speed': {cli.label: {'argv0': cli.argv0, 'samples_s': cli.samples,
                                      'failures': cli.failures} for cli in clis}}
    return rows, data


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--reference-ros2', metavar='PATH',
                        help='a reference `ros2` executable, or the prefix it is installed in')
    parser.add_argument('--runs', type=int, default=RUNS, help='timed runs per command')
    options = parser.parse_args()
    load_before = os.getloadavg()
    with session('cli_speed') as current:
        print(f'cli_speed: domain {current.domain}, load average {load_before[0]:.2f} '
              f'{load_before[1]:.2f} {load_before[2]:.2f}', flush=True)
        clis = measure(current, options.reference_ros2, max(1, options.runs))
    load_after = os.getloadavg()
    header = ('command', 'ours (ms)', 'reference (ms)', 'ratio', 'target', 'verdict')
    lines = [header, *table_lines(clis)]
    widths = [max(len(line[i]) for line in lines) for i in range(len(header))]
    print()
    for index, line in enumerate(lines):
        cells = (cell.ljust(width) for cell, width in zip(line, widths, strict=True))
        print(' | '.join(cells).rstrip())
        if index == 0:
            print('-+-'.join('-' * width for width in widths))
    print(f'\nmedians of {options.runs} runs after one warm-up; ours: {clis[0].argv0}'
          + (f'; reference: {clis[1].argv0}' if len(clis) > 1 else ''))
    print(f'load average: before {load_before[0]:.2f}, after {load_after[0]:.2f} '
          f'(1 min), {os.cpu_count()} cores')
    print('samples (ms), in order:')
    for name in row_names():
        spread = '; '.join(f'{cli.label} ' + ' '.join(f'{v * 1000:.0f}' for v in
                                                      cli.samples.get(name, []))
                           for cli in clis)
        print(f'  {name}: {spread}')
    for cli in clis:
        for name, messages in cli.failures.items():
            print(f'{cli.label} failed `{name}` {len(messages)}x: {messages[-1]}')
    if len(clis) > 1:
        for note in output_differences(*clis):
            print(f'output differs: {note}')
    sys.exit(1 if clis[0].failures else 0)


if __name__ == '__main__':
    main()
