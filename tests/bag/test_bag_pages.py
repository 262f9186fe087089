"""The Advanced pages "Recording a bag from a node (Python)" (its three nodes) and "Reading
from a bag file (Python)", typed as written (tests/data/bag_pages/), then played with `ros2 bag`.

The nodes run as the pages' `ros2 run` runs their entry points (python on the module), in a
fresh directory where the pages' relative bag names land.
"""

from __future__ import annotations

import itertools
import re
import shutil
import signal
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from example_interfaces.msg import Int32
from std_msgs.msg import String

from support import REPO, Background, ros2, wait_until

PAGES = REPO / 'tests' / 'data' / 'bag_pages'
COUNT = 40  # messages the recorder page records (its reader page replays them in 4 s)
PUBLISHED_LINE = re.compile(r'\[INFO\] \[[\d.]+\] \[simple_bag_reader\]: Publish serialized '
                            r'data to chatter\n')


@pytest.fixture
def run_page(ros_env: dict[str, str], tmp_path: Path) -> Iterator:
    """run_page('x.py') starts a page's node in tmp_path; all are ended at teardown."""
    started: list[subprocess.Popen] = []

    def start(name: str) -> subprocess.Popen:
        shutil.copy(PAGES / name, tmp_path / name)
        # Into a file, so that a test can read what the node has printed so far.
        with open(tmp_path / f'{name}.log', 'w') as log:
            process = subprocess.Popen([sys.executable, name], cwd=tmp_path, env=ros_env,
                                       stdout=log, stderr=subprocess.STDOUT, text=True,
                                       stdin=subprocess.DEVNULL)
        process.log_path = tmp_path / f'{name}.log'
        started.append(process)
        return process

    yield start
    for process in started:
        if process.poll() is None:
            process.kill()
        process.wait(timeout=10)


def output(process: subprocess.Popen) -> str:
    """What a page's node has printed so far."""
    return process.log_path.read_text(errors='replace')


def interrupt(process: subprocess.Popen) -> str:
    """Ctrl-C, as the page says to end a node; its output."""
    process.send_signal(signal.SIGINT)
    process.wait(timeout=15)
    return output(process)


def test_simple_bag_recorder_then_ros2_bag_play_then_the_reader_page(
        run_page, probe, ros_env, tmp_path):
    talker = probe.node.create_publisher(String, 'chatter', 10)
    recorder = run_page('simple_bag_recorder.py')
    probe.spin_until(lambda: talker.get_subscription_count() == 1, 15, 'the recorder node')
    # Enough messages that the reader page (below) still publishes them when the probe has
    # discovered it: it publishes one every 0.1 s from its start, volatile, as the page writes it.
    for i in range(COUNT):
        talker.publish(String(data=f'Hello World: {i}'))
        probe.spin_for(0.05)
    probe.spin_for(0.5)
    interrupt(recorder)  # the page's main has no try: Ctrl-C ends it with a traceback
    assert (tmp_path / 'my_bag' / 'metadata.yaml').is_file()
    probe.node.destroy_publisher(talker)

    info = ros2(ros_env, 'bag', 'info', str(tmp_path / 'my_bag'))
    assert f'Messages:          {COUNT}\n' in info.stdout, info
    assert f'Topic: chatter | Type: std_msgs/msg/String | Count: {COUNT} |' in info.stdout

    heard = probe.collect(String, '/chatter')
    with Background(probe):
        played = ros2(ros_env, 'bag', 'play', str(tmp_path / 'my_bag'), timeout=30)
        wait_until(lambda: len(heard) == COUNT, 5, 'the played messages')
    assert played.returncode == 0, played
    assert [m.data for m in heard] == [f'Hello World: {i}' for i in range(COUNT)]

    heard.clear()
    reader = run_page('simple_bag_reader.py')
    last = f'Hello World: {COUNT - 1}'
    probe.spin_until(lambda: heard and heard[-1].data == last, 15,
                     "the reader page's last message")
    # What was published before the probe matched the page's volatile publisher is lost, as
    # for any late subscriber; the rest arrives in order.
    first = int(heard[0].data.rsplit(' ', 1)[1])
    assert first < COUNT - 5, first
    assert [m.data for m in heard] == [f'Hello World: {i}' for i in range(first, COUNT)]
    # The page logs each message after publishing it: its last line may follow the message.
    wait_until(lambda: len(PUBLISHED_LINE.findall(output(reader))) == COUNT, 10,
               "the reader page's last line")
    printed = interrupt(reader)
    assert len(PUBLISHED_LINE.findall(printed)) == COUNT, printed
    assert 'Traceback' not in printed


def test_data_generator_node_records_one_message_a_second(run_page, probe, ros_env, tmp_path):
    generator = run_page('data_generator_node.py')
    # From the moment the node has opened its bag: its timer fires every second from then on.
    probe.spin_until((tmp_path / 'timed_synthetic_bag').is_dir, 15, 'the bag to be opened')
    probe.spin_for(3.5)
    interrupt(generator)
    info = ros2(ros_env, 'bag', 'info', str(tmp_path / 'timed_synthetic_bag'))
    count = int(re.search(r'Messages:          (\d+)\n', info.stdout)[1])
    assert count in (3, 4), info.stdout
    duration = float(re.search(r'Duration:          ([\d.]+)s\n', info.stdout)[1])
    assert abs(duration - (count - 1)) < 0.2, info.stdout

    heard = probe.collect(Int32, '/synthetic')
    with Background(probe):
        played = ros2(ros_env, 'bag', 'play', str(tmp_path / 'timed_synthetic_bag'),
                      timeout=30)
        wait_until(lambda: len(heard) == count, 5, 'the played messages')
    assert played.returncode == 0, played
    assert [m.data for m in heard] == list(range(count))


def test_data_generator_executable_writes_100_seconds_at_once(run_page, probe, ros_env,
                                                              tmp_path, launch):
    generator = run_page('data_generator_executable.py')
    assert generator.wait(timeout=30) == 0
    info = ros2(ros_env, 'bag', 'info', str(tmp_path / 'big_synthetic_bag'))
    assert 'Messages:          100\n' in info.stdout, info
    assert 'Duration:          99.000000000s\n' in info.stdout, info.stdout

    # Played at the pace of its stamps: one a second (two seconds are enough to see it).
    received: list[tuple[float, int]] = []
    probe.node.create_subscription(
        Int32, '/synthetic', lambda m: received.append((time.monotonic(), m.data)), 10)
    player = launch(argv=['ros2', 'bag', 'play', '--disable-keyboard-controls',
                          str(tmp_path / 'big_synthetic_bag')])
    probe.spin_until(lambda: len(received) >= 3, 15, 'three played messages')
    assert [d for _, d in received[:3]] == [0, 1, 2]
    gaps = [b[0] - a[0] for a, b in itertools.pairwise(received[:3])]
    assert all(0.8 < gap < 1.2 for gap in gaps), gaps
    player.stop()
