"""The whole repository is ruff clean (rules in pyproject.toml)."""

import subprocess
import sys

from support import REPO


def test_ruff_check_passes():
    result = subprocess.run([sys.executable, '-m', 'ruff', 'check', '--no-cache', str(REPO)],
                            capture_output=True, text=True, cwd=REPO, timeout=120)
    assert result.returncode == 0, result.stdout + result.stderr
