"""`ros2 run tf2_tools view_frames`: listen to tf, then draw the frame tree with Graphviz.

As Jazzy's: it listens for `--wait-time` seconds (5.0), asks its own Buffer's `tf2_frames`
service (tf2_msgs/srv/FrameGraph) for the frames as YAML, logs the response, and writes
frames_YYYY-MM-DD_HH.MM.SS.gv (or `-o NAME`.gv) and the PDF that Graphviz's `dot` lays out.
"""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
import threading
import time
from typing import Any

import rclpy
import yaml
from node_runtime.spinning import ros_session
from rclpy.executors import SingleThreadedExecutor
from tf2_msgs.srv import FrameGraph

SERVICE_WAIT = 10.0  # seconds for our own tf2_frames service to appear and answer
DOT_TIMEOUT = 60.0  # seconds for Graphviz to lay out the PDF
MISSING_DOT = ('Graphviz is not installed (no `dot` command): {gv} is written, the PDF is '
               'not -- fix: apt install graphviz (or your system\'s graphviz package)')


def parse_args(argv: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(
        prog='view_frames',
        description='Create a diagram of the TF frames being broadcast over ROS')
    parser.add_argument(
        '--wait-time', '-t', type=float, default=5.0,
        help='Listen to the /tf topic for this many seconds before rendering the frame tree')
    parser.add_argument('-o', '--output', help='Output filename')
    args = parser.parse_args(argv)
    if not 0.0 <= args.wait_time <= 3600.0:
        parser.error(f'--wait-time must be between 0 and 3600 seconds, got {args.wait_time}')
    return args


def main() -> int:
    args = parse_args(rclpy.utilities.remove_ros_args(sys.argv)[1:])
    # Ctrl-C or SIGTERM ends the listening early with 0 (no graph written).
    with ros_session(sys.argv) as stop:
        return view_frames(args, stop)


def view_frames(args: argparse.Namespace, stop: threading.Event) -> int:
    import tf2_ros

    node = rclpy.create_node('view_frames')
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    logger = node.get_logger()
    # node= gives the buffer its `tf2_frames` service, which is what we ask below.
    buffer = tf2_ros.Buffer(node=node)
    listener = tf2_ros.TransformListener(buffer, node, spin_thread=False)  # noqa: F841
    try:
        logger.info(f'Listening to tf data for {args.wait_time} seconds...')
        deadline = time.monotonic() + args.wait_time
        while time.monotonic() < deadline and not stop.is_set():
            executor.spin_once(timeout_sec=min(0.1, max(0.0, deadline - time.monotonic())))
        if stop.is_set():
            return 0

        logger.info('Generating graph...')
        result = ask_frames(node, executor, stop)
        if result is None:
            if not stop.is_set():
                logger.error(f'Service call failed: tf2_frames did not answer within '
                             f'{SERVICE_WAIT:g} s')
            return 0 if stop.is_set() else 1
        logger.info('Result:' + str(result))
        data = yaml.safe_load(result.frame_yaml) or {}

        if args.output is not None:
            frames_gv, frames_pdf = f'{args.output}.gv', f'{args.output}.pdf'
        else:
            stamp = time.strftime('%Y-%m-%d_%H.%M.%S')
            frames_gv, frames_pdf = f'frames_{stamp}.gv', f'frames_{stamp}.pdf'
        logger.info(f'Exporting graph in {frames_pdf} file...')
        with open(frames_gv, 'w') as handle:
            handle.write(generate_dot(data, node.get_clock().now().seconds_nanoseconds()))
        return render_pdf(frames_gv, frames_pdf, logger)
    finally:
        executor.shutdown(timeout_sec=1.0)
        node.destroy_node()


def ask_frames(node: Any, executor: SingleThreadedExecutor, stop: threading.Event
               ) -> FrameGraph.Response | None:
    """Our own buffer's answer to tf2_frames, or None after SERVICE_WAIT (or a stop)."""
    client = node.create_client(FrameGraph, 'tf2_frames')
    try:
        deadline = time.monotonic() + SERVICE_WAIT
        future = None
        while time.monotonic() < deadline and not stop.is_set():
            if future is None and client.service_is_ready():
                future = client.call_async(FrameGraph.Request())
            if future is not None and future.done():
                return future.result()
            executor.spin_once(timeout_sec=0.05)
        return None
    finally:
        node.destroy_client(client)


def render_pdf(frames_gv: str, frames_pdf: str, logger: Any) -> int:
    dot = shutil.which('dot')
    if dot is None:
        logger.error(MISSING_DOT.format(gv=frames_gv))
        return 1
    try:
        done = subprocess.run([dot, '-Tpdf', frames_gv, '-o', frames_pdf], timeout=DOT_TIMEOUT,
                              capture_output=True, text=True)
    except subprocess.TimeoutExpired:
        logger.error(f'dot did not finish {frames_pdf} within {DOT_TIMEOUT:g} s')
        return 1
    if done.returncode != 0:
        logger.error(f'dot could not write {frames_pdf}: {done.stderr.strip()}')
        return 1
    return 0


def _quoted(name: Any) -> str:
    """A dot string literal: frame ids may hold quotes or backslashes."""
    return '"' + str(name).replace('\\', '\\\\').replace('"', '\\"') + '"'


def generate_dot(data: dict, recorded_time: tuple[int, int]) -> str:
    """The frame tree as upstream's view_frames writes it: one labelled edge per frame."""
    if not data:
        return 'digraph G { "No tf data received" }'
    lines = ['digraph G {']
    roots = []
    for child, info in data.items():
        parent = info['parent']
        label = (f'Broadcaster: {info["broadcaster"]}\\n'
                 f'Average rate: {info["rate"]}\\n'
                 f'Buffer length: {info["buffer_length"]}\\n'
                 f'Most recent transform: {info["most_recent_transform"]}\\n'
                 f'Oldest transform: {info["oldest_transform"]}\\n')
        lines.append(f'{_quoted(parent)} -> {_quoted(child)}[label=" {label}"];')
        if parent not in data:
            roots.append(parent)
    # The legend box hangs (invisibly) above a root, so it sits at the top of the page.
    root = roots[-1] if roots else next(iter(data))
    seconds = recorded_time[0] + recorded_time[1] / 1e9
    lines += ['edge [style=invis];',
              ' subgraph cluster_legend { style=bold; color=black; label ="view_frames Result";',
              f'"Recorded at time: {seconds}"[ shape=plaintext ] ;',
              f'}}->{_quoted(root)};', '}']
    return '\n'.join(lines)


if __name__ == '__main__':
    sys.exit(main())
