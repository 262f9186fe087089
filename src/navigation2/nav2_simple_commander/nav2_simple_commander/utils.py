"""Process helpers the demos use to stop a simulator they started (e.g. `gz sim`)."""

from __future__ import annotations

import os
import signal
import subprocess


def find_os_processes(name: str) -> list[tuple[str, str]]:
    """(pid, command line) of each running process whose command line starts with name."""
    listing = subprocess.check_output(['ps', '-eo', 'pid=,args='], text=True)
    found = []
    for line in listing.splitlines():
        pid, _, command = line.strip().partition(' ')
        command = command.strip()
        if pid and command.startswith(name):
            found.append((pid, command))
    return found


def kill_process(pid: int | str) -> None:
    """SIGKILL one process, saying whether it worked."""
    try:
        os.kill(int(pid), signal.SIGKILL)
        print(f'Successfully killed process with PID: {pid}')
    except Exception as error:  # reported and not raised, as upstream does
        print(f'Failed to kill process with PID: {pid}. Error: {error}')


def kill_os_processes(name: str) -> None:
    """SIGKILL every process whose command line starts with name."""
    processes = find_os_processes(name)
    if not processes:
        print(f'No processes found starting with {name}')
    for pid, _ in processes:
        kill_process(pid)
