"""Setup time: scripts/setup on a fresh clone (warm pip cache), then the no-change rerun."""

from __future__ import annotations

import os
import subprocess
import tempfile
import time
from pathlib import Path

from common import REPO, Row, verdict

FRESH_LIMIT_S = 180.0
RERUN_LIMIT_S = 20.0


def _timed(command: list[str], cwd: Path) -> float:
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(('AMENT_', 'COLCON_', 'CMAKE_PREFIX', 'VIRTUAL_ENV', '_ROS_'))}
    env['PATH'] = ':'.join(p for p in env['PATH'].split(':') if '.venv' not in p)
    start = time.monotonic()
    subprocess.run(command, cwd=cwd, env=env, check=True, timeout=900,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.monotonic() - start


def run(_session=None) -> tuple[list[Row], dict]:
    with tempfile.TemporaryDirectory(prefix='bench-setup-') as scratch:
        clone = Path(scratch) / 'ws'
        subprocess.run(['git', 'clone', '-q', str(REPO), str(clone)], check=True, timeout=120)
        fresh = _timed(['scripts/setup'], clone)
        rerun = _timed(['scripts/setup'], clone)
    rows = [
        Row('setup', 'fresh clone, warm pip cache', f'{fresh:.1f} s', '< 180 s',
            verdict(fresh < FRESH_LIMIT_S)),
        Row('setup', 'no-change rerun', f'{rerun:.2f} s', '< 20 s', verdict(rerun < RERUN_LIMIT_S)),
    ]
    return rows, {'setup': {'fresh_s': fresh, 'rerun_s': rerun}}
