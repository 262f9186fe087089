"""Two "machines": network namespaces joined by a veth pair, turtlesim in one, the controller in
the other, discovering each other over the veth (multicast, then unicast static peers only).

The namespaces have no other interface than their loopback and their end of the veth, so no
packet leaves them. Needs root (CI runs as root); skipped with the reason otherwise.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import time
from pathlib import Path

import pytest
from PySide6.QtGui import QImage

from support import RosProcess, executable, leased_domain, ros_environment

pytestmark = pytest.mark.skipif(
    os.geteuid() != 0 or shutil.which('ip') is None,
    reason='needs root and iproute2 (ip netns) to create network namespaces')

RED, GREEN = (255, 0, 0), (0, 255, 0)


def ip(*args: str) -> None:
    subprocess.run(['ip', *args], check=True, capture_output=True, timeout=10)


class Machines:
    """Namespaces <tag>-sim and <tag>-ctl, veth 10.200.<n>.1 <-> 10.200.<n>.2, nothing else."""

    def __init__(self, multicast: bool) -> None:
        n = os.getpid() % 250 + 1
        tag = f'ts{os.getpid() % 100000}{"m" if multicast else "u"}'
        self.sim, self.ctl = f'{tag}-sim', f'{tag}-ctl'
        self.sim_ip, self.ctl_ip = f'10.200.{n}.1', f'10.200.{n}.2'
        ip('netns', 'add', self.sim)
        ip('netns', 'add', self.ctl)
        veth_sim, veth_ctl = f'{tag}a', f'{tag}b'
        ip('link', 'add', veth_sim, 'netns', self.sim, 'type', 'veth',
           'peer', 'name', veth_ctl, 'netns', self.ctl)
        for ns, dev, address in ((self.sim, veth_sim, self.sim_ip),
                                 (self.ctl, veth_ctl, self.ctl_ip)):
            ip('-n', ns, 'link', 'set', 'lo', 'up')
            ip('-n', ns, 'address', 'add', f'{address}/24', 'dev', dev)
            ip('-n', ns, 'link', 'set', dev, 'multicast', 'on' if multicast else 'off')
            ip('-n', ns, 'link', 'set', dev, 'up')
            if multicast:  # discovery multicast (239.255.0.1) goes over the veth
                ip('-n', ns, 'route', 'add', '224.0.0.0/4', 'dev', dev)
        # Fast DDS lists the interfaces once, when a process starts, and leaves out one that is
        # not up yet. The kernel reports a veth's carrier a moment after both ends are set up,
        # and over a second later right after another namespace was deleted: the second
        # variant's controller then started on 'NO-CARRIER ... state DOWN', announced only its
        # loopback address and was never heard back (half of the runs).
        deadline = time.monotonic() + 10
        while not all(self._is_up(ns, dev) for ns, dev in ((self.sim, veth_sim),
                                                           (self.ctl, veth_ctl))):
            assert time.monotonic() < deadline, 'the veth pair did not come up within 10 s'
            time.sleep(0.05)

    @staticmethod
    def _is_up(ns: str, dev: str) -> bool:
        shown = subprocess.run(['ip', '-n', ns, '-o', 'link', 'show', 'dev', dev],
                               capture_output=True, text=True, timeout=10).stdout
        return 'state UP' in shown and 'NO-CARRIER' not in shown

    def close(self) -> None:
        for ns in (self.sim, self.ctl):
            subprocess.run(['ip', 'netns', 'delete', ns], capture_output=True, timeout=10)

    def run(self, ns: str, argv: list[str], env: dict[str, str], log: Path) -> RosProcess:
        return RosProcess(['ip', 'netns', 'exec', ns, *argv], env, log)


def machine_env(domain: int, static_peer: str | None) -> dict[str, str]:
    env = ros_environment(domain)
    env['ROS_AUTOMATIC_DISCOVERY_RANGE'] = 'SUBNET'
    # Two machines share no memory: without this the namespaces' processes (one /dev/shm,
    # one machine id) would also pass data through Fast DDS's shared-memory transport.
    env['FASTDDS_BUILTIN_TRANSPORTS'] = 'UDPv4'
    if static_peer:
        env['ROS_STATIC_PEERS'] = static_peer
    return env


def colour_counts(png: Path) -> dict[tuple[int, int, int], int]:
    image = QImage(str(png))
    assert not image.isNull(), f'no canvas at {png}'
    counts: dict[tuple[int, int, int], int] = {RED: 0, GREEN: 0}
    for y in range(0, image.height()):
        for x in range(0, image.width()):
            colour = image.pixelColor(x, y)
            rgb = (colour.red(), colour.green(), colour.blue())
            if rgb in counts:
                counts[rgb] += 1
    return counts


@pytest.mark.parametrize('discovery', ['multicast', 'static_peers'])
def test_turtlesim_and_controller_on_two_machines(discovery, tmp_path):
    multicast = discovery == 'multicast'
    machines = Machines(multicast)
    started: list[RosProcess] = []
    try:
        with leased_domain() as domain:
            png = tmp_path / 'canvas.png'
            sim = machines.run(machines.sim, [executable('turtlesim', 'turtlesim_node'),
                                              '--headless', '--canvas-png', str(png)],
                               machine_env(domain, None if multicast else machines.ctl_ip),
                               tmp_path / 'turtlesim.log')
            started.append(sim)
            sim.wait_for_output(r'Spawning turtle \[turtle1\]', timeout=20)
            ctl = machines.run(machines.ctl,
                               [executable('my_robot_controller', 'turtle_controller')],
                               machine_env(domain, None if multicast else machines.sim_ip),
                               tmp_path / 'controller.log')
            started.append(ctl)
            # The turtle starts at x = 5.54 (right of 5.5): green first, red once it crossed.
            ctl.wait_for_output(r'pen colour applied: green', timeout=30)
            ctl.wait_for_output(r'pen colour applied: red', timeout=30)
            time.sleep(1.0)  # a little more red on the canvas
            assert sim.stop() == 0, sim.output
            counts = colour_counts(png)
            assert counts[RED] > 50 and counts[GREEN] > 50, counts
            assert ctl.stop() == 0, ctl.output
            for process in started:
                assert 'Traceback' not in process.output, process.output
    finally:
        for process in reversed(started):
            process.stop()
        machines.close()
