"""`ros2 bag list`, `ros2 bag convert`, rosbag2_py's read orders, and `ros2 bag play`'s
--clock, topic selection (--regex, --exclude-topics) and --playback-until-nsec, as Jazzy's."""

from __future__ import annotations

import re

import pytest
from rclpy.qos import DurabilityPolicy, QoSProfile, ReliabilityPolicy
from rclpy.serialization import serialize_message
from rosgraph_msgs.msg import Clock
from std_msgs.msg import String
from test_rosbag2_py import open_reader, read_all, write_bag

import rosbag2_py
from support import Background, ros2

ERROR = r'\[ERROR\] \[ros2bag\]: '


def test_list_names_the_plugins_as_jazzy(ros_env):
    listed = ros2(ros_env, 'bag', 'list', 'storage')
    assert (listed.returncode, listed.stdout, listed.stderr) == (0, 'mcap\nsqlite3\n', '')
    assert ros2(ros_env, 'bag', 'list', 'converter').stdout == ''
    verbose = ros2(ros_env, 'bag', 'list', 'decompressor', '-v').stdout
    assert verbose == ('available decompressor plugins are:\nname: zstd\n'
                       '\tZstd implementation for rosbag2 decompressor\n'
                       '\ttype: rosbag2_compression_zstd::ZstdDecompressor\n'
                       '\tbase_class: rosbag2_compression::BaseDecompressorInterface\n')
    refused = ros2(ros_env, 'bag', 'list', 'codec')
    assert refused.returncode == 2 and "invalid choice: 'codec'" in refused.stderr


def test_convert_writes_the_bags_the_options_describe(ros_env, tmp_path):
    source = tmp_path / 'source'
    write_bag(source, 'mcap')
    options = tmp_path / 'out.yaml'
    options.write_text(f'output_bags:\n- uri: {tmp_path / "only_a"}\n  storage_id: sqlite3\n'
                       f'  topics: [/a]\n- uri: {tmp_path / "all"}\n  all_topics: true\n'
                       '  compression_mode: message\n  compression_format: zstd\n')
    converted = ros2(ros_env, 'bag', 'convert', '-i', str(source), 'mcap', '-o', str(options))
    assert (converted.returncode, converted.stderr) == (0, ''), converted
    only_a = read_all(open_reader(tmp_path / 'only_a'))
    assert [(t, s) for t, _, s in only_a] == [('/a', 1000 + i * 200) for i in range(5)]
    assert open_reader(tmp_path / 'only_a').get_metadata().storage_identifier == 'sqlite3'
    assert read_all(open_reader(tmp_path / 'all')) == read_all(open_reader(source))
    assert open_reader(tmp_path / 'all').get_metadata().compression_mode == 'MESSAGE'

    # Bad input: one line, and the input bag as it was.
    before = sorted((p.name, p.stat().st_size) for p in source.iterdir())
    bad = tmp_path / 'bad.yaml'
    bad.write_text('[{key: value}]')
    for argv, expect in (
            (['-i', str(source), '-o', str(bad)], "must hold the top level key "
             "'output_bags'"),
            (['-i', str(tmp_path / 'nope'), '-o', str(options)], 'does not exist'),
            (['-i', str(source), 'mcap', 'x', '-o', str(options)], '--input expects 1 or 2')):
        refused = ros2(ros_env, 'bag', 'convert', *argv)
        assert refused.returncode == 1, refused
        assert re.fullmatch(ERROR + '.*' + re.escape(expect) + '.*\n', refused.stderr), refused
    assert sorted((p.name, p.stat().st_size) for p in source.iterdir()) == before


@pytest.mark.parametrize('storage_id', ['mcap', 'sqlite3'])
def test_read_orders(tmp_path, storage_id):
    bag = tmp_path / 'bag'
    write_bag(bag, storage_id)
    reader = open_reader(bag)
    assert reader.set_read_order(rosbag2_py.ReadOrder(reverse=True))
    assert [s for _, _, s in read_all(reader)] == [1900 - i * 100 for i in range(10)]
    reader.seek(1450)  # reversed: from the last message at or before the stamp, backwards
    assert [s for _, _, s in read_all(reader)] == [1400, 1300, 1200, 1100, 1000]
    assert not reader.set_read_order(rosbag2_py.ReadOrder(
        sort_by=rosbag2_py.ReadOrderSortBy.PublishedTimestamp))
    file_order = reader.set_read_order(rosbag2_py.ReadOrder(
        sort_by=rosbag2_py.ReadOrderSortBy.File))
    assert file_order == (storage_id == 'mcap')  # as Jazzy's plugins: MCAP only
    if not file_order:  # refused: still reversed, so nothing lies at or before stamp 0
        reader.seek(0)
        assert not reader.has_next()
        assert reader.set_read_order(rosbag2_py.ReadOrder())
    reader.seek(0)
    assert [s for _, _, s in read_all(reader)] == [1000 + i * 100 for i in range(10)]


def test_play_publishes_clock_and_plays_what_is_selected(probe, ros_env, tmp_path):
    """/c, /a, /b every 100 ms of bag time (1 s): --regex keeps /a and /b, --exclude-topics
    drops /b, --playback-until-nsec stops after /a's sixth message, /clock runs at 20 Hz."""
    bag = tmp_path / 'abc'
    writer = rosbag2_py.SequentialWriter()
    writer.open(rosbag2_py.StorageOptions(uri=str(bag), storage_id='mcap'),
                rosbag2_py.ConverterOptions('cdr', 'cdr'))
    for name in ('/a', '/b', '/c'):
        writer.create_topic(rosbag2_py.TopicMetadata(
            id=0, name=name, type='std_msgs/msg/String', serialization_format='cdr'))
    start = 1_700_000_000_000_000_000
    for i in range(10):
        for k, name in enumerate(('/a', '/b', '/c')):
            stamp = start + i * 100_000_000 + k
            writer.write(name, serialize_message(String(data=f'{name} {i}')), stamp)
    writer.close()

    reliable = QoSProfile(depth=100, reliability=ReliabilityPolicy.RELIABLE)
    received = {name: probe.collect(String, name, reliable) for name in ('/a', '/b', '/c')}
    clock = probe.collect(Clock, '/clock', QoSProfile(
        depth=100, reliability=ReliabilityPolicy.BEST_EFFORT))
    until = start + 5 * 100_000_000
    with Background(probe):
        played = ros2(ros_env, 'bag', 'play', str(bag), '--clock', '20', '-e', '/(a|b)',
                      '--exclude-topics', '/b', '--playback-until-nsec', str(until),
                      '--disable-keyboard-controls', timeout=30)
    assert played.returncode == 0, played
    assert f'Playback until timestamp: {until}\n' in played.stderr
    assert [m.data for m in received['/a']] == [f'/a {i}' for i in range(6)]
    assert received['/b'] == [] and received['/c'] == []
    stamps = [m.clock.sec * 1_000_000_000 + m.clock.nanosec for m in clock]
    assert len(stamps) >= 5, stamps  # ~0.5 s of playing at 20 Hz
    assert stamps == sorted(stamps), stamps
    assert start <= stamps[0] and stamps[-1] <= until + 2e8, stamps  # stops with playing
    assert stamps[-1] - stamps[0] >= 2e8  # the clock moved with the bag, not stood still


def test_play_refuses_bad_selection_and_clock(ros_env, tmp_path):
    bag = tmp_path / 'bag'
    write_bag(bag, 'mcap')
    refused = ros2(ros_env, 'bag', 'play', str(bag), '--regex', '(')
    assert refused.returncode == 1
    assert re.fullmatch(ERROR + r"--regex: '\(' is not a valid regular expression .*\n",
                        refused.stderr), refused
    refused = ros2(ros_env, 'bag', 'play', str(bag), '--clock', '0')
    assert refused.returncode == 2 and '0 is not in the valid range (> 0.0)' in refused.stderr


def test_player_services_pause_step_seek_rate_and_stop(launch, probe, tmp_path):
    """`ros2 bag play --start-paused` answers Jazzy's ~/is_paused, ~/get_rate, ~/set_rate,
    ~/play_next, ~/seek, ~/toggle_paused and ~/stop (rosbag2_interfaces)."""
    from rosbag2_interfaces import srv

    # Offered transient-local: what play_next publishes before the probe matched still
    # arrives.
    latched = QoSProfile(depth=10, reliability=ReliabilityPolicy.RELIABLE,
                         durability=DurabilityPolicy.TRANSIENT_LOCAL)
    bag = tmp_path / 'steps'
    writer = rosbag2_py.SequentialWriter()
    writer.open(rosbag2_py.StorageOptions(uri=str(bag), storage_id='mcap'),
                rosbag2_py.ConverterOptions('cdr', 'cdr'))
    writer.create_topic(rosbag2_py.TopicMetadata(0, '/t', 'std_msgs/msg/String', 'cdr',
                                                 [latched]))
    start = 1_700_000_000_000_000_000
    for i in range(10):
        writer.write('/t', serialize_message(String(data=f't {i}')), start + i * 1_000_000_000)
    writer.close()

    heard = probe.collect(String, '/t', latched)
    player = launch(argv=['ros2', 'bag', 'play', str(bag), '--start-paused',
                          '--disable-keyboard-controls'])

    def call(kind, name, **fields):
        return probe.call(kind, f'/rosbag2_player/{name}', kind.Request(**fields))

    def step(expect: str) -> None:
        assert call(srv.PlayNext, 'play_next').success
        probe.spin_until(lambda: heard and heard[-1].data == expect, 10, expect)

    assert call(srv.IsPaused, 'is_paused').paused
    assert call(srv.GetRate, 'get_rate').rate == 1.0
    assert not call(srv.SetRate, 'set_rate', rate=0.0).success
    assert call(srv.SetRate, 'set_rate', rate=4.0).success
    assert call(srv.GetRate, 'get_rate').rate == 4.0
    step('t 0')
    step('t 1')
    seek = srv.Seek.Request()
    seek.time.sec = (start + 7_000_000_000) // 1_000_000_000
    assert probe.call(srv.Seek, '/rosbag2_player/seek', seek).success
    step('t 7')
    call(srv.TogglePaused, 'toggle_paused')  # resumes: t 8 and t 9 at 4x, then the end
    probe.spin_until(lambda: heard[-1].data == 't 9', 10, 't 9 after resuming')
    assert player.wait(timeout=10) == 0
    assert [m.data for m in heard] == ['t 0', 't 1', 't 7', 't 8', 't 9']
    assert re.search(r'\[rosbag2_player\]: Resuming play\.\n', player.output), player.output

    player = launch(argv=['ros2', 'bag', 'play', str(bag), '--start-paused',
                          '--disable-keyboard-controls'])
    assert call(srv.IsPaused, 'is_paused').paused
    call(srv.Stop, 'stop')
    assert player.wait(timeout=10) == 0
    assert len(heard) == 5
