"""ros2 run tf2_ros tf2_monitor [FRAME_A FRAME_B]: delays and rates of what /tf carries."""
import sys
import threading
from collections import defaultdict, deque

import rclpy
import rclpy.utilities
from node_runtime.spinning import SIGNAL_CHECK_PERIOD, ros_session
from rclpy.executors import SingleThreadedExecutor
from rclpy.node import Node
from rclpy.time import Time
from tf2_msgs.msg import TFMessage
from tf2_py import TransformException
from tf2_ros.buffer import Buffer
from tf2_ros.transform_listener import (
    DYNAMIC_LISTENER_QOS,
    STATIC_LISTENER_QOS,
    TransformListener,
)

AUTHORITY = '<no authority available>'  # upstream's: DDS does not say who published
KEEP = 1000  # samples per frame, as upstream
REPORT_EVERY = 21  # half-second ticks between reports (~10 s), as upstream


class TfMonitor(Node):
    def __init__(self, frame_a: str = '', frame_b: str = '') -> None:
        super().__init__('tf2_monitor_main')
        self.frame_a, self.frame_b = frame_a, frame_b
        self.buffer = Buffer(node=self)
        self.listener = TransformListener(self.buffer, self)
        self.delays: dict[str, deque[float]] = defaultdict(lambda: deque(maxlen=KEEP))
        self.authority_delays: deque[float] = deque(maxlen=KEEP)
        self.arrivals: deque[float] = deque(maxlen=KEEP)
        self.lock = threading.Lock()
        self.create_subscription(TFMessage, '/tf', self.on_tf, DYNAMIC_LISTENER_QOS)
        self.create_subscription(TFMessage, '/tf_static', self.on_tf, STATIC_LISTENER_QOS)

    def now(self) -> float:
        return self.get_clock().now().nanoseconds / 1e9

    def on_tf(self, message: TFMessage) -> None:
        now = self.now()
        with self.lock:
            offsets = []
            for transform in message.transforms:
                stamp = transform.header.stamp
                offset = now - (stamp.sec + stamp.nanosec / 1e9)
                self.delays[transform.child_frame_id].append(offset)
                offsets.append(offset)
            self.authority_delays.append(sum(offsets) / max(1, len(offsets)))
            self.arrivals.append(now)

    def chain(self) -> list[str]:
        """The frames from frame_a up to where it meets frame_b, then down to frame_b."""
        up_a = self._ancestors(self.frame_a)
        up_b = self._ancestors(self.frame_b)
        common = next((frame for frame in up_a if frame in up_b), None)
        if common is None:
            return []
        return up_a[:up_a.index(common) + 1] + list(reversed(up_b[:up_b.index(common)]))

    def _ancestors(self, frame: str) -> list[str]:
        parents = {}
        for line in self.buffer.all_frames_as_string().splitlines():
            words = line.split()  # Frame CHILD exists with parent PARENT.
            parents[words[1]] = words[-1].rstrip('.')
        chain = [frame]
        while chain[-1] in parents and len(chain) <= len(parents):
            chain.append(parents[chain[-1]])
        return chain

    def report(self, specific: bool, average: float, maximum: float) -> str:
        lines = ['', '', '']
        if specific:
            chain = self.chain()
            lines += [f'RESULTS: for {self.frame_a} to {self.frame_b}',
                      'Chain is: ' + ' -> '.join(chain),
                      f'Net delay     avg = {average:g}: max = {maximum:g}']
        else:
            lines.append('RESULTS: for all Frames')
        lines += ['', 'Frames:']
        with self.lock:
            wanted = set(self.chain()) if specific else None
            for frame in sorted(self.delays):
                if wanted is not None and frame not in wanted:
                    continue
                delays = self.delays[frame]
                lines.append(f'Frame: {frame}, published by {AUTHORITY}, Average Delay: '
                             f'{sum(delays) / len(delays):g}, Max Delay: {max(0.0, *delays):g}')
            lines += ['', 'All Broadcasters:']
            if self.arrivals:
                span = max(1e-8, self.arrivals[-1] - self.arrivals[0])
                delays = self.authority_delays
                lines.append(f'Node: {AUTHORITY} {len(self.arrivals) / span:g} Hz, Average '
                             f'Delay: {sum(delays) / len(delays):g} Max Delay: '
                             f'{max(0.0, *delays):g}')
        return '\n'.join(lines)


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv if argv is None else argv
    args = rclpy.utilities.remove_ros_args(argv)[1:]
    with ros_session(argv) as stop:
        if len(args) not in (0, 2):
            rclpy.logging.get_logger('tf2_monitor_main').info(
                'TF_Monitor: usage: tf2_monitor framea frameb')
            return 255
        node = TfMonitor(*args)
        executor = SingleThreadedExecutor()
        executor.add_node(node)
        spinner = threading.Thread(target=_spin_until, args=(executor, stop))
        spinner.start()
        try:
            _monitor(node, bool(args), stop)
        finally:
            stop.set()
            spinner.join()
            executor.shutdown(timeout_sec=1.0)
            node.destroy_node()
    return 0


def _spin_until(executor: SingleThreadedExecutor, stop: threading.Event) -> None:
    """Spin on a thread of its own (the report loop sleeps), until stopped; joined before
    shutdown, so no rclpy call is still running when the process ends."""
    while not stop.is_set() and rclpy.ok():
        executor.spin_once(timeout_sec=SIGNAL_CHECK_PERIOD)


def _monitor(node: TfMonitor, specific: bool, stop: threading.Event) -> None:
    if specific:
        while not stop.is_set():
            ready, why = node.buffer.can_transform_core(node.frame_a, node.frame_b, Time())
            if ready:
                break
            node.get_logger().info(
                f'Waiting for transform {node.frame_a} ->  {node.frame_b}: {why}',
                throttle_duration_sec=1.0)
            stop.wait(0.5)
        print(f'Gathering data on {node.frame_a} -> {node.frame_b} for 10 seconds...',
              flush=True)
    else:
        print('Gathering data on all frames for 10 seconds...', flush=True)
    average = maximum = 0.0
    ticks = 0
    while not stop.is_set():
        ticks += 1
        if specific:
            try:
                stamp = node.buffer.lookup_transform(node.frame_a, node.frame_b,
                                                     Time()).header.stamp
                delay = node.now() - (stamp.sec + stamp.nanosec / 1e9)
                average = 0.01 * delay + 0.99 * average
                maximum = max(maximum, delay)
            except TransformException as error:
                node.get_logger().warning(f'Transform Exception {error}',
                                          throttle_duration_sec=5.0)
        stop.wait(0.5)
        if ticks > REPORT_EVERY - 1:
            ticks = 0
            print(node.report(specific, average, maximum), flush=True)


if __name__ == '__main__':
    sys.exit(main())
