"""Setup time: scripts/setup on a fresh clone, then the no-change rerun (issue 24 item 1).

The fresh clone runs twice: with the machine's caches as they are (pip's wheels, and ccache's
objects from an earlier build of any clone: the demo-ready figure a returning learner sees),
and with an empty ccache (every interface package compiled again). `--cold` adds a run with
empty pip, uv, npm and ccache caches (everything downloaded and compiled).

    scripts/ws python bench/setup_time.py [--cold]
"""

from __future__ import annotations

import os
import subprocess
import tempfile
import time
from pathlib import Path

from common import REPO, Row, verdict

WARM_LIMIT_S = 90.0
COLD_LIMIT_S = 180.0
RERUN_LIMIT_S = 1.0


def _timed(command: list[str], cwd: Path, extra_env: dict[str, str] | None = None) -> float:
    env = {k: v for k, v in os.environ.items()
           if not k.startswith(('AMENT_', 'COLCON_', 'CMAKE_PREFIX', 'VIRTUAL_ENV', '_ROS_'))}
    env['PATH'] = ':'.join(p for p in env['PATH'].split(':') if '.venv' not in p)
    env.update(extra_env or {})
    start = time.monotonic()
    subprocess.run(command, cwd=cwd, env=env, check=True, timeout=900,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.monotonic() - start


def _fresh_clone(scratch: Path, name: str, extra_env: dict[str, str] | None = None
                 ) -> tuple[float, float]:
    """(setup of a fresh clone, its no-change rerun) in seconds."""
    clone = scratch / name
    subprocess.run(['git', 'clone', '-q', str(REPO), str(clone)], check=True, timeout=120)
    fresh = _timed(['scripts/setup'], clone, extra_env)
    return fresh, _timed(['scripts/setup'], clone, extra_env)


def run(_session=None, cold: bool = False) -> tuple[list[Row], dict]:
    with tempfile.TemporaryDirectory(prefix='bench-setup-') as scratch_dir:
        scratch = Path(scratch_dir)
        warm, rerun = _fresh_clone(scratch, 'warm')
        no_ccache, _ = _fresh_clone(scratch, 'no-ccache', {'CCACHE_DIR': str(scratch / 'cc')})
        rows = [
            Row('setup', 'fresh clone, warm pip cache and ccache', f'{warm:.1f} s',
                f'<= {WARM_LIMIT_S:.0f} s', verdict(warm <= WARM_LIMIT_S)),
            Row('setup', 'fresh clone, warm pip cache, empty ccache', f'{no_ccache:.1f} s'),
            Row('setup', 'no-change rerun', f'{rerun:.2f} s', f'< {RERUN_LIMIT_S:.0f} s',
                verdict(rerun < RERUN_LIMIT_S)),
        ]
        data = {'fresh_s': warm, 'fresh_empty_ccache_s': no_ccache, 'rerun_s': rerun}
        if cold:
            empty = {'CCACHE_DIR': str(scratch / 'cc2'), 'PIP_CACHE_DIR': str(scratch / 'pip'),
                     'UV_CACHE_DIR': str(scratch / 'uv'), 'npm_config_cache': str(scratch / 'npm')}
            data['cold_s'], _ = _fresh_clone(scratch, 'cold', empty)
            rows.append(Row('setup', 'fresh clone, empty pip, uv, npm and ccache caches',
                            f'{data["cold_s"]:.1f} s', f'<= {COLD_LIMIT_S:.0f} s',
                            verdict(data['cold_s'] <= COLD_LIMIT_S)))
    return rows, {'setup': data}


if __name__ == '__main__':
    import argparse

    from report import table
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--cold', action='store_true', help='also with empty pip/uv/npm/ccache')
    print(table(run(cold=parser.parse_args().cold)[0]))
