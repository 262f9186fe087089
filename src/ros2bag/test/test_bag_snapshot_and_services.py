"""rosbag2 features of Jazzy's `ros2 bag` beyond plain record/play: storage config files
(MCAP writer options, SQLite3 pragmas), snapshot mode, --use-sim-time, the recorder's
services and write_split events, the player's ~/burst and ~/play services."""

from __future__ import annotations

import signal
import sqlite3
from pathlib import Path

import pytest
from mcap.records import Chunk
from mcap.stream_reader import StreamReader
from rclpy.serialization import deserialize_message, serialize_message
from rosgraph_msgs.msg import Clock
from std_msgs.msg import String

import rosbag2_py
from rosbag2_interfaces import msg as bag_msg
from rosbag2_interfaces import srv
from ws_testing import ros2

PAYLOAD = 'x' * 40


def _write(uri: Path, count: int, storage: str = 'mcap', **options) -> rosbag2_py.SequentialWriter:
    writer = rosbag2_py.SequentialWriter()
    writer.open(rosbag2_py.StorageOptions(uri=str(uri), storage_id=storage, **options),
                rosbag2_py.ConverterOptions())
    writer.create_topic(rosbag2_py.TopicMetadata(0, '/chatter', 'std_msgs/msg/String', 'cdr'))
    for i in range(count):
        writer.write('/chatter', serialize_message(String(data=f'm{i} {PAYLOAD}')), 1000 + i)
    return writer


def _read(uri: Path, config: str = '') -> list[tuple[str, int]]:
    reader = rosbag2_py.SequentialReader()
    reader.open(rosbag2_py.StorageOptions(uri=str(uri), storage_config_uri=config),
                rosbag2_py.ConverterOptions())
    found = []
    while reader.has_next():
        _topic, data, stamp = reader.read_next()
        found.append((deserialize_message(data, String).data.split()[0], stamp))
    return found


def _chunks(path: Path) -> list[str]:
    with open(path, 'rb') as stream:
        return [r.compression for r in StreamReader(stream, emit_chunks=True).records
                if isinstance(r, Chunk)]


def test_storage_config_files_for_mcap_and_sqlite3(tmp_path):
    config = tmp_path / 'mcap.yaml'
    config.write_text('compression: "Zstd"\nchunkSize: 1024\nnoChunkCRC: false\n')
    _write(tmp_path / 'zstd', 50, storage_config_uri=str(config)).close()
    chunks = _chunks(tmp_path / 'zstd' / 'zstd_0.mcap')
    assert len(chunks) > 1 and set(chunks) == {'zstd'}, chunks
    assert len(_read(tmp_path / 'zstd')) == 50
    # The file is laid over the preset: zstd_small's 4 MiB chunks, uncompressed.
    config.write_text('compression: None\n')
    _write(tmp_path / 'small', 50, storage_preset_profile='zstd_small',
           storage_config_uri=str(config)).close()
    assert _chunks(tmp_path / 'small' / 'small_0.mcap') == ['']
    for options in ('noChunking: true\n', 'noMessageIndex: true\n', 'noSummary: true\n'):
        config.write_text(options)
        bag = tmp_path / options.split(':')[0]
        _write(bag, 20, storage_config_uri=str(config)).close()
        assert _read(bag) == [(f'm{i}', 1000 + i) for i in range(20)], options
    assert _chunks(tmp_path / 'noChunking' / 'noChunking_0.mcap') == []

    pragmas = tmp_path / 'sqlite.yaml'
    pragmas.write_text('write:\n  pragmas: ["user_version = 42", "journal_mode = WAL"]\n'
                       'read:\n  pragmas: ["cache_size = 1000"]\n')
    _write(tmp_path / 'db', 3, storage='sqlite3', storage_config_uri=str(pragmas)).close()
    (database,) = (tmp_path / 'db').glob('*.db3')
    with sqlite3.connect(database) as db:
        assert db.execute('PRAGMA user_version').fetchone() == (42,)
        assert db.execute('PRAGMA journal_mode').fetchone() == ('wal',)
    assert _read(tmp_path / 'db', str(pragmas)) == [('m0', 1000), ('m1', 1001), ('m2', 1002)]


@pytest.mark.parametrize('storage, text, error', [
    ('mcap', 'chunk_size: 3\n', "unknown MCAP writer option 'chunk_size' (allowed: noChunkCRC,"),
    ('mcap', 'noChunking: 3\n', "'noChunking' must be true or false, got 3"),
    ('mcap', 'compression: zstd\n', "'compression' must be one of None, Lz4, Zstd, got 'zstd'"),
    ('mcap', 'chunkSize: -1\n', "'chunkSize' must be a non-negative integer (bytes), got -1"),
    ('sqlite3', 'write:\n  pragmas: ["a; b"]\n', "'write.pragmas' entry 'a; b' holds ';'"),
    ('sqlite3', 'writ:\n  pragmas: []\n', "unknown SQLite3 section 'writ' (allowed: read, write)"),
    ('sqlite3', 'write:\n  pragmas: ["user_version = = 3"]\n',
     "SQLite3 storage config: 'PRAGMA user_version = = 3;' failed: near \"=\": syntax error"),
])
def test_a_bad_storage_config_file_is_one_line_and_creates_nothing(tmp_path, storage, text,
                                                                   error):
    config = tmp_path / 'bad.yaml'
    config.write_text(text)
    with pytest.raises(RuntimeError) as failure:
        _write(tmp_path / 'never', 1, storage=storage, storage_config_uri=str(config))
    assert error in str(failure.value) and '\n' not in str(failure.value)
    assert not (tmp_path / 'never').exists()


def test_sequential_writer_snapshot_mode(tmp_path):
    size = len(serialize_message(String(data=f'm0 {PAYLOAD}')))
    writer = _write(tmp_path / 'snap', 10, snapshot_mode=True, max_cache_size=3 * size)
    assert writer.take_snapshot() is True
    writer.write('/chatter', serialize_message(String(data=f'late {PAYLOAD}')), 5000)
    writer.close()  # what the buffer holds at the end is not written
    assert _read(tmp_path / 'snap') == [('m7', 1007), ('m8', 1008), ('m9', 1009)]
    with pytest.raises(RuntimeError, match=r'^Max cache size must be greater than 0 when '
                       r'snapshot mode is enabled$'):
        _write(tmp_path / 'none', 1, snapshot_mode=True, max_cache_size=0)
    assert not (tmp_path / 'none').exists()
    plain = _write(tmp_path / 'plain', 1)
    assert plain.take_snapshot() is False
    plain.close()


def test_record_refusals(ros_env, tmp_path):
    refused = ros2(ros_env, 'bag', 'record', '-a', '--use-sim-time', '--no-discovery',
                   '-o', str(tmp_path / 'a'))
    assert refused.stderr == (
        '[ERROR] [ros2bag]: --use-sim-time and --no-discovery both set, but are incompatible '
        'settings. The /clock topic needs to be discovered to record with sim time.\n')
    options = rosbag2_py.RecordOptions()
    options.all_topics = True
    with pytest.raises(RuntimeError, match=r'^Max cache size must be greater than 0'):
        rosbag2_py.Recorder().record(rosbag2_py.StorageOptions(
            uri=str(tmp_path / 'b'), snapshot_mode=True, max_cache_size=0), options)
    config = tmp_path / 'bad.yaml'
    config.write_text('compresion: Zstd\n')
    refused = ros2(ros_env, 'bag', 'record', '-a', '--storage-config-file', str(config),
                   '-o', str(tmp_path / 'c'))
    assert refused.stderr.startswith(
        f"[ERROR] [ros2bag]: Storage config file '{config}': unknown MCAP writer option "
        "'compresion' (allowed: ")
    assert refused.stderr.count('\n') == 1
    assert not any((tmp_path / name).exists() for name in 'abc')


def test_recorder_snapshot_sim_time_services_and_split_events(launch, probe, tmp_path):
    """One recorder: sim time from /clock, snapshot mode with a ring buffer of three
    messages, zstd chunks from the storage config file, pause/resume/is_paused, a split."""
    size = len(serialize_message(String(data=f'a0 {PAYLOAD}')))
    config = tmp_path / 'mcap.yaml'
    config.write_text('compression: Zstd\n')
    bag = tmp_path / 'snap'
    recorder = launch(argv=['ros2', 'bag', 'record', '--topics', '/chatter', '--use-sim-time',
                            '--snapshot-mode', '--max-cache-size', str(3 * size), '-o', str(bag),
                            '--storage-config-file', str(config)])
    talker = probe.node.create_publisher(String, '/chatter', 20)
    clock = probe.node.create_publisher(Clock, '/clock', 10)
    events = probe.collect(bag_msg.WriteSplitEvent, '/events/write_split')
    sim_now = [100]

    def tick() -> None:
        message = Clock()
        message.clock.sec = sim_now[0]
        clock.publish(message)

    def say(*words: str) -> None:
        for word in words:
            talker.publish(String(data=f'{word} {PAYLOAD}'))
        talker.wait_for_all_acked()
        probe.spin_for(1.0)  # the recorder takes them before the next service request

    recorder.wait_for_output(r'use_sim_time set, waiting for /clock before starting recording')
    probe.spin_until(lambda: talker.get_subscription_count() == 0 and probe.node.count_publishers(
        '/events/write_split') == 1, 10, 'the recorder')
    assert 'Subscribed to topic' not in recorder.output  # nothing before the first /clock
    timer = probe.node.create_timer(0.1, tick)
    probe.spin_until(lambda: 'Sim time /clock found, starting recording.' in recorder.output,
                     15, 'the recorder to see /clock')
    probe.spin_until(lambda: talker.get_subscription_count() == 1, 10, 'the subscription')
    say(*(f'a{i}' for i in range(6)))
    assert probe.call(srv.IsPaused, '/rosbag2_recorder/is_paused',
                      srv.IsPaused.Request()).paused is False
    probe.call(srv.Pause, '/rosbag2_recorder/pause', srv.Pause.Request())
    assert probe.call(srv.IsPaused, '/rosbag2_recorder/is_paused',
                      srv.IsPaused.Request()).paused is True
    say('paused')
    probe.call(srv.Resume, '/rosbag2_recorder/resume', srv.Resume.Request())
    recorder.wait_for_output(r'\[INFO\] \[[\d.]+\] \[rosbag2_recorder\]: Resuming recording\.')
    assert probe.call(srv.Snapshot, '/rosbag2_recorder/snapshot',
                      srv.Snapshot.Request()).success is True
    probe.call(srv.SplitBagfile, '/rosbag2_recorder/split_bagfile', srv.SplitBagfile.Request())
    probe.spin_until(lambda: len(events) == 1, 5, 'the write_split event')
    assert (events[0].closed_file, events[0].opened_file, events[0].node_name) == (
        str(bag / 'snap_0.mcap'), str(bag / 'snap_1.mcap'), '/rosbag2_recorder')
    sim_now[0] = 200
    probe.spin_for(0.5)  # a few /clock ticks of the new time
    say('b0', 'b1')
    assert probe.call(srv.Snapshot, '/rosbag2_recorder/snapshot',
                      srv.Snapshot.Request()).success is True
    say('c0')  # left in the buffer: never written
    probe.node.destroy_timer(timer)
    recorder.popen.send_signal(signal.SIGINT)
    assert recorder.popen.wait(timeout=15) == 0, recorder.output
    probe.spin_until(lambda: len(events) == 2, 5, 'the closing write_split event')
    assert (events[1].closed_file, events[1].opened_file) == (str(bag / 'snap_1.mcap'), '')

    assert 'Pausing recording.' in recorder.output
    found = _read(bag)
    assert found == [('a3', 100 * 10**9), ('a4', 100 * 10**9), ('a5', 100 * 10**9),
                     ('b0', 200 * 10**9), ('b1', 200 * 10**9)], found
    assert set(_chunks(bag / 'snap_0.mcap')) == {'zstd'}


def test_player_burst_and_play_services(launch, probe, tmp_path):
    bag = tmp_path / 'six'
    writer = rosbag2_py.SequentialWriter()
    writer.open(rosbag2_py.StorageOptions(uri=str(bag), storage_id='sqlite3'),
                rosbag2_py.ConverterOptions())
    writer.create_topic(rosbag2_py.TopicMetadata(0, '/chatter', 'std_msgs/msg/String', 'cdr'))
    for i in range(6):
        writer.write('/chatter', serialize_message(String(data=f'm{i}')), (10 + i) * 10**9)
    writer.close()
    config = tmp_path / 'read.yaml'
    config.write_text('read:\n  pragmas: ["cache_size = 1000"]\n')
    heard = probe.collect(String, '/chatter')
    services = {'burst': srv.Burst, 'play': srv.Play, 'play_next': srv.PlayNext,
                'set_rate': srv.SetRate, 'resume': srv.Resume, 'pause': srv.Pause}
    for name, kind in services.items():  # before the player: no first-call race (probe.client)
        probe.client(kind, f'/rosbag2_player/{name}')
    player = launch(argv=['ros2', 'bag', 'play', '--start-paused', str(bag),
                          '--storage-config-file', str(config)])
    probe.spin_until(lambda: probe.node.count_publishers('/chatter') == 1, 10, 'the player')

    def call(kind, name, **fields):
        return probe.call(kind, f'/rosbag2_player/{name}', kind.Request(**fields))

    assert call(srv.Burst, 'burst', num_messages=3).actually_burst == 3
    player.wait_for_output(r'\[INFO\] \[[\d.]+\] \[rosbag2_player\]: Burst 3 messages\.')
    assert call(srv.Play, 'play').success is False
    player.wait_for_output(r'\[WARN\] \[[\d.]+\] \[rosbag2_player\]: Trying to play\(\) while '
                           r'in playback, dismissing request\.')
    assert call(srv.PlayNext, 'play_next').success is True
    assert call(srv.SetRate, 'set_rate', rate=0.05).success is True  # 20 s per bag second
    call(srv.Resume, 'resume')
    assert call(srv.Burst, 'burst', num_messages=1).actually_burst == 0
    player.wait_for_output(r'\[WARN\] \[[\d.]+\] \[rosbag2_player\]: Burst can only be used '
                           r'when in the paused state\.')
    call(srv.Pause, 'pause')
    assert call(srv.Burst, 'burst', num_messages=0).actually_burst == 2  # all that is left
    assert player.popen.wait(timeout=15) == 0, player.output  # the bag is over
    probe.spin_until(lambda: len(heard) == 6, 5, 'the six messages')
    assert [m.data for m in heard] == [f'm{i}' for i in range(6)]
