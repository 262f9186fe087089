"""foxglove_bridge under 200 turtles (12,500 pose msg/s): share delivered, CPU, latency.

For each subprotocol and for 1 and 5 clients (tests/foxglove_client/bench.mjs, the
@foxglove/ws-protocol client), every client subscribes to all 200 /turtleN/pose channels and
to /bench_stamp (builtin_interfaces/Time stamped at publish, 100 Hz, for the latency). The
share is what the clients received over what turtlesim published in the same window, which
`ros2 topic hz /turtle1/pose` measures at the same time.

    scripts/ws python bench/foxglove.py [--turtles 200] [--window 10]
"""

from __future__ import annotations

import argparse
import json
import re
import subprocess
import threading
import time

from builtin_interfaces.msg import Time

from common import REPO, Row, Session, cpu_seconds, percentile, session
from scale import _spawn_all

CLIENT = REPO / 'tests' / 'foxglove_client' / 'bench.mjs'
WARM_UP_S = 4.0
PROTOCOLS = ('foxglove.websocket.v1', 'foxglove.sdk.v1')


class StampPublisher:
    """Publishes the wall-clock time at 100 Hz on /bench_stamp from a probe node."""

    def __init__(self, sess: Session) -> None:
        self.probe = sess.probe('bench_stamp')
        self.publisher = self.probe.node.create_publisher(Time, '/bench_stamp', 10)
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    def _run(self) -> None:
        while not self.stop.wait(0.01):
            now = time.time_ns()
            self.publisher.publish(Time(sec=now // 10**9, nanosec=now % 10**9))

    def close(self) -> None:
        self.stop.set()
        self.thread.join(timeout=2)
        self.probe.close()


def hz(sess: Session, seconds: float) -> subprocess.Popen[str]:
    return subprocess.Popen(['timeout', '-s', 'INT', f'{seconds:.0f}', 'ros2', 'topic', 'hz',
                             '/turtle1/pose', '--window', '2000'], env=sess.env,
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def run_config(sess: Session, url: str, bridge_pid: int, protocol: str, clients: int,
               turtles: int, window: float) -> tuple[dict, list[Row]]:
    procs = [subprocess.Popen(['node', str(CLIENT), url, protocol, str(WARM_UP_S), str(window)],
                              stdout=subprocess.PIPE, text=True) for _ in range(clients)]
    time.sleep(WARM_UP_S)
    rate = hz(sess, window)
    cpu_before, started = cpu_seconds(bridge_pid), time.monotonic()
    results = [json.loads(p.communicate(timeout=window + 60)[0].strip().splitlines()[-1])
               for p in procs]
    cpu = 100 * (cpu_seconds(bridge_pid) - cpu_before) / (time.monotonic() - started)
    hz_out = rate.communicate(timeout=30)[0]
    rates = [float(r) for r in re.findall(r'average rate: ([\d.]+)', hz_out)]
    topic_hz = rates[-1] if rates else float('nan')
    nominal = 62.5 * turtles * window  # turtlesim's 16 ms tick
    shares = [r['poses'] / nominal for r in results]
    turtle1_hz = [r['turtle1'] / window for r in results]
    latencies = [x for r in results for x in r['latencies']]
    data = {'protocol': protocol, 'clients': clients, 'topic_hz': topic_hz,
            'nominal': nominal, 'received': [r['poses'] for r in results],
            'client_turtle1_hz': turtle1_hz,
            'topics_subscribed': [r['topics'] for r in results], 'shares': shares,
            'bridge_cpu_percent': cpu, 'latency_ms_p50': percentile(latencies, 50),
            'latency_ms_p95': percentile(latencies, 95), 'latency_samples': len(latencies)}
    print(f'bench foxglove: {json.dumps(data)}', flush=True)
    label = f'{protocol}, {clients} client{"s" if clients > 1 else ""}'
    rows = [
        Row('foxglove', f'{label}: poses received per client of {turtles} x 62.5 Hz (min)',
            f'{min(shares):.1%} ({min(r["poses"] for r in results) / window:,.0f} msg/s)'),
        Row('foxglove', f'{label}: /turtle1/pose at the client (min) vs ros2 topic hz',
            f'{min(turtle1_hz):.1f} Hz vs {topic_hz:.1f} Hz'),
        Row('foxglove', f'{label}: bridge CPU', f'{cpu:.0f} % of a core'),
        Row('foxglove', f'{label}: latency publish -> client p50 / p95',
            f'{data["latency_ms_p50"]:.1f} / {data["latency_ms_p95"]:.1f} ms'),
    ]
    return data, rows


def run(sess: Session, turtles: int = 200, window: float = 10.0) -> tuple[list[Row], dict]:
    sim = sess.start('turtlesim', 'turtlesim_node', '--headless')
    sim.wait_for_output(r'Spawning turtle')
    probe = sess.probe('bench_foxglove_spawn')
    try:
        _spawn_all(probe, turtles - 1)
    finally:
        probe.close()
    stamps = StampPublisher(sess)
    bridge = sess.start('foxglove_bridge', 'foxglove_bridge', '--ros-args', '-p', 'port:=0')
    port = bridge.wait_for_output(r'Server listening on port (\d+)', 30).group(1)
    time.sleep(2.0)  # the bridge's first graph polls advertise every topic
    rows, data = [], []
    try:
        for protocol in PROTOCOLS:
            for clients in (1, 5):
                result, new_rows = run_config(sess, f'ws://127.0.0.1:{port}', bridge.popen.pid,
                                              protocol, clients, turtles, window)
                data.append(result)
                rows += new_rows
    finally:
        stamps.close()
    return rows, {'foxglove': data}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('--turtles', type=int, default=200)
    parser.add_argument('--window', type=float, default=10.0)
    args = parser.parse_args()
    with session('foxglove') as sess:
        rows, _data = run(sess, args.turtles, args.window)
    for row in rows:
        print(f'| {row.metric} | {row.value} |')


if __name__ == '__main__':
    main()
