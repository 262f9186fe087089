"""CPU use of turtlesim (one turtle) and turtle_controller while the demo drives."""

from __future__ import annotations

import time

from common import Row, Session, cpu_seconds, verdict

WARM_UP_S = 3.0
DURATION_S = 30.0
# Issue 24 item 3 asks turtlesim for <= 2 % of a core in the demo; the controller keeps the
# earlier 5 % bar.
TARGETS = {'turtlesim': 2.0, 'turtle_controller': 5.0}


def run(session: Session, duration: float = DURATION_S) -> tuple[list[Row], dict]:
    sim = session.start('turtlesim', 'turtlesim_node', '--headless')
    sim.wait_for_output(r'Spawning turtle')
    controller = session.start('my_robot_controller', 'turtle_controller')
    time.sleep(WARM_UP_S)
    pids = {'turtlesim': sim.popen.pid, 'turtle_controller': controller.popen.pid}
    before = {name: cpu_seconds(pid) for name, pid in pids.items()}
    started = time.monotonic()
    time.sleep(duration)
    elapsed = time.monotonic() - started
    percent = {name: 100 * (cpu_seconds(pid) - before[name]) / elapsed
               for name, pid in pids.items()}
    rows = [Row('CPU', f'{name}, {elapsed:.0f} s of the demo', f'{value:.1f} % of a core',
                f'<= {TARGETS[name]:g} %', verdict(value <= TARGETS[name]))
            for name, value in percent.items()]
    return rows, {'cpu': percent}
