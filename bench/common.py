"""What every benchmark shares: processes on a leased domain, percentiles, CPU readings."""

from __future__ import annotations

import os
import sys
import time
from collections.abc import Iterator
from contextlib import ExitStack, contextmanager
from dataclasses import dataclass, field
from pathlib import Path

BENCH = Path(__file__).resolve().parent
REPO = BENCH.parent
RESULTS = BENCH / 'results'
# The process and domain helpers are the tests' own (tests/support.py): one copy of them.
sys.path.insert(0, str(REPO / 'tests'))

from support import RosProcess, TestNode, executable, leased_domain, ros_environment  # noqa: E402

__all__ = ['RESULTS', 'Row', 'Session', 'TestNode', 'cpu_seconds', 'executable', 'percentile',
           'session', 'verdict']


def percentile(samples: list[float], pct: float) -> float:
    ordered = sorted(samples)
    if not ordered:
        return float('nan')
    index = min(len(ordered) - 1, max(0, round(pct / 100 * (len(ordered) - 1))))
    return ordered[index]


def verdict(met: bool) -> str:
    return 'met' if met else 'MISSED'


def cpu_seconds(pid: int) -> float:
    """User + system CPU time the process has used so far."""
    fields = Path(f'/proc/{pid}/stat').read_text().rsplit(')', 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf('SC_CLK_TCK')


@dataclass
class Row:
    """One line of the results table."""

    benchmark: str
    metric: str
    value: str
    target: str = ''
    verdict: str = ''


@dataclass
class Session:
    """Processes started for one benchmark on one leased ROS domain; all stop on exit."""

    domain: int
    log_dir: Path
    processes: list[RosProcess] = field(default_factory=list)

    @property
    def env(self) -> dict[str, str]:
        return ros_environment(self.domain)

    def start(self, package: str, name: str, *args: str) -> RosProcess:
        return self.start_argv([executable(package, name), *args])

    def start_argv(self, argv: list[str]) -> RosProcess:
        log = self.log_dir / f'{len(self.processes):02d}-{Path(argv[-1]).stem}.log'
        process = RosProcess(argv, self.env, log)
        self.processes.append(process)
        return process

    def probe(self, name: str = 'bench_probe') -> TestNode:
        return TestNode(self.domain, name)


@contextmanager
def session(name: str) -> Iterator[Session]:
    log_dir = RESULTS / 'logs' / name
    log_dir.mkdir(parents=True, exist_ok=True)
    with ExitStack() as stack:
        domain = stack.enter_context(leased_domain())
        current = Session(domain, log_dir)
        try:
            yield current
        finally:
            for process in reversed(current.processes):
                process.stop()


def wait_until(predicate, timeout: float, what: str) -> None:
    deadline = time.monotonic() + timeout
    while not predicate():
        if time.monotonic() > deadline:
            raise TimeoutError(f'timed out after {timeout} s waiting for {what}')
        time.sleep(0.05)
