"""The MuJoCo simulator (mujoco_sim) with the diffbot in the room world: how fast it can run
with every sensor on (360-ray scan at 10 Hz, 320x240 camera at 15 Hz, IMU at 100 Hz), with the
camera off, and next to the baseline of MuJoCo stepping the same model with no ROS; what it
costs at real time; and `ros2 launch diffbot_bringup diffbot_sim.launch.py` to the first scan.

`python bench/sim.py [--seconds S] [--runs N]` alone, or `scripts/bench --only sim`.
The real-time factor is sim seconds (from /clock) per wall second, read by a probe node.
"""

from __future__ import annotations

import argparse
import os
import signal
import time
from pathlib import Path

from common import Row, Session, cpu_seconds, executable, percentile, session, verdict

SECONDS = 8.0  # of wall time per speed measurement
RUNS = 3  # launches for the start-up figure
BOUND = 30.0  # seconds: slower than this is a failure, not a figure


def robot_params(path: Path, **values) -> Path:
    import yaml
    from ament_index_python.packages import get_package_share_directory
    urdf = (Path(get_package_share_directory('diffbot_description')) / 'urdf' /
            'diffbot.urdf').read_text()
    world = Path(get_package_share_directory('mujoco_sim')) / 'worlds' / 'room.xml'
    values = {'robot_description': urdf, 'world': str(world), **values}
    path.write_text(yaml.safe_dump({'mujoco_sim': {'ros__parameters': values}}))
    return path


def bare_mujoco_factor(seconds: float) -> float:
    """The baseline: the same compiled model stepped in a Python loop, no sensors, no ROS."""
    import mujoco
    from ament_index_python.packages import get_package_share_directory
    from mujoco_sim.world import RobotSpec, World
    urdf = (Path(get_package_share_directory('diffbot_description')) / 'urdf' /
            'diffbot.urdf').read_text()
    world = World(str(Path(get_package_share_directory('mujoco_sim')) / 'worlds' / 'room.xml'),
                  RobotSpec(urdf, (0, 0, 0), ('left_wheel_joint', 'right_wheel_joint'),
                            'camera_link', 60.0, (320, 240), 'imu_link'))
    model, data = world.model, world.data
    started = time.monotonic()
    while time.monotonic() - started < seconds:
        for _ in range(500):
            mujoco.mj_step(model, data)
    return data.time / (time.monotonic() - started)


def sim_factor(session: Session, name: str, seconds: float, **params) -> tuple[float, float]:
    """(real-time factor, CPU seconds per wall second) of one simulator run."""
    from rosgraph_msgs.msg import Clock
    probe = session.probe()
    clock: list[tuple[float, float]] = []
    probe.node.create_subscription(
        Clock, '/clock', lambda m: clock.append(
            (time.monotonic(), m.clock.sec + m.clock.nanosec * 1e-9)), 10)
    params_file = robot_params(session.log_dir / f'{name}.yaml', **params)
    process = session.start_argv([executable('mujoco_sim', 'mujoco_sim'), '--ros-args',
                                  '--params-file', str(params_file)])
    try:
        probe.spin_until(lambda: len(clock) > 10, BOUND, 'the simulator to publish /clock')
        probe.spin_for(1.0)  # past start-up
        first, cpu0 = clock[-1], cpu_seconds(process.popen.pid)
        probe.spin_for(seconds)
        last, cpu1 = clock[-1], cpu_seconds(process.popen.pid)
    finally:
        probe.close()
        os.killpg(process.popen.pid, signal.SIGINT)
        process.wait(timeout=15)
    wall = last[0] - first[0]
    return (last[1] - first[1]) / wall, (cpu1 - cpu0) / wall


def time_to_first_scan(session: Session, argv: list[str], runs: int) -> list[float]:
    from sensor_msgs.msg import LaserScan
    probe = session.probe()
    scans: list[LaserScan] = []
    probe.node.create_subscription(LaserScan, '/scan', scans.append, 10)
    samples = []
    try:
        for _ in range(runs):
            scans.clear()
            started = time.monotonic()
            process = session.start_argv(argv)
            try:
                probe.spin_until(lambda: bool(scans), BOUND, 'the first /scan')
                samples.append(time.monotonic() - started)
            finally:
                os.killpg(process.popen.pid, signal.SIGINT)
                process.wait(timeout=15)
            probe.spin_for(0.5)  # the stopped run's last messages, not the next run's
    finally:
        probe.close()
    return samples


def run(session: Session, seconds: float = SECONDS, runs: int = RUNS) -> tuple[list[Row], dict]:
    full, _ = sim_factor(session, 'full', seconds, real_time_factor=0.0)
    no_camera, _ = sim_factor(session, 'no_camera', seconds, real_time_factor=0.0,
                              camera=False)
    at_real_time, cpu = sim_factor(session, 'real_time', seconds, real_time_factor=1.0)
    bare = bare_mujoco_factor(min(seconds, 3.0))
    starts = time_to_first_scan(session, ['ros2', 'launch', 'diffbot_bringup',
                                          'diffbot_sim.launch.py', 'rviz:=false'], runs)
    # The baseline: the simulator alone, without launch and robot_state_publisher.
    params_file = robot_params(session.log_dir / 'alone.yaml')
    alone = time_to_first_scan(session, [executable('mujoco_sim', 'mujoco_sim'), '--ros-args',
                                         '--params-file', str(params_file)], runs)
    rows = [
        Row('sim', 'real-time factor as fast as possible, scan 360 rays@10 Hz + camera '
            '320x240@15 Hz + IMU@100 Hz', f'{full:.1f}', '>= 1.0', verdict(full >= 1.0)),
        Row('sim', 'real-time factor as fast as possible, camera off', f'{no_camera:.1f}'),
        Row('sim', 'baseline: the same model in a bare mj_step loop (no sensors, no ROS)',
            f'{bare:.1f}'),
        Row('sim', 'at real_time_factor 1 (all sensors): factor reached, CPU of one core',
            f'{at_real_time:.3f}, {cpu * 100:.0f} %'),
        Row('sim', f'ros2 launch diffbot_sim.launch.py to first /scan (warm), p50 / max of '
            f'{len(starts)}', f'{percentile(starts, 50):.2f} / {max(starts):.2f} s', '<= 5 s',
            verdict(max(starts) <= 5.0)),
        Row('sim', f'baseline: the mujoco_sim executable alone to first /scan (warm), p50 / '
            f'max of {len(alone)}', f'{percentile(alone, 50):.2f} / {max(alone):.2f} s'),
    ]
    return rows, {'sim': {'full': full, 'no_camera': no_camera, 'bare': bare,
                          'real_time': at_real_time, 'cpu': cpu, 'starts': starts,
                          'alone': alone}}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--seconds', type=float, default=SECONDS)
    parser.add_argument('--runs', type=int, default=RUNS)
    options = parser.parse_args()
    with session('sim') as current:
        rows, _ = run(current, options.seconds, options.runs)
    for row in rows:
        print(f'{row.metric}: {row.value} {row.target} {row.verdict}')


if __name__ == '__main__':
    main()
