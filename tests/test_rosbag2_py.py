"""rosbag2_py: Jazzy's Python bag API, and one implementation with `ros2 bag`.

Bags written by rosbag2_py are read back by it, by `ros2 bag` and by the `mcap` library;
bags recorded by `ros2 bag` are read by rosbag2_py; bad input is one clear line.
"""

from __future__ import annotations

import datetime
import hashlib
import threading
from pathlib import Path

import pytest
from rclpy.serialization import deserialize_message, serialize_message
from std_msgs.msg import String

import rosbag2_py
from support import Background, ros2, wait_until


def write_bag(path: Path, storage_id: str, compression: str = '') -> None:
    """/a and /b, five messages each, interleaved at 100 ns steps."""
    if compression:
        writer = rosbag2_py.SequentialCompressionWriter(rosbag2_py.CompressionOptions(
            compression_format='zstd', compression_queue_size=0,  # 0: drop no message
            compression_mode=rosbag2_py.compression_mode_from_string(compression)))
    else:
        writer = rosbag2_py.SequentialWriter()
    writer.open(rosbag2_py.StorageOptions(uri=str(path), storage_id=storage_id),
                rosbag2_py.ConverterOptions('cdr', 'cdr'))
    for name in ('/a', '/b'):
        writer.create_topic(rosbag2_py.TopicMetadata(
            id=0, name=name, type='std_msgs/msg/String', serialization_format='cdr'))
    for i in range(10):
        topic = '/a' if i % 2 == 0 else '/b'
        writer.write(topic, serialize_message(String(data=f'{topic} {i}')), 1000 + i * 100)
    writer.close()


def read_all(reader) -> list[tuple[str, str, int]]:
    found = []
    while reader.has_next():
        topic, data, stamp = reader.read_next()
        found.append((topic, deserialize_message(data, String).data, stamp))
    return found


def open_reader(path: Path, storage_id: str = ''):
    reader = rosbag2_py.SequentialReader()
    reader.open(rosbag2_py.StorageOptions(uri=str(path), storage_id=storage_id),
                rosbag2_py.ConverterOptions('', ''))
    return reader


@pytest.mark.parametrize(('storage_id', 'compression'),
                         [('mcap', ''), ('sqlite3', ''), ('mcap', 'message'),
                          ('sqlite3', 'file'), ('sqlite3', 'message')])
def test_write_read_filter_seek_and_metadata(tmp_path, storage_id, compression):
    bag = tmp_path / 'bag'
    write_bag(bag, storage_id, compression)
    reader = open_reader(bag, storage_id)
    assert sorted((t.name, t.type) for t in reader.get_all_topics_and_types()) == [
        ('/a', 'std_msgs/msg/String'), ('/b', 'std_msgs/msg/String')]
    topics = ['/a' if i % 2 == 0 else '/b' for i in range(10)]
    assert read_all(reader) == [(t, f'{t} {i}', 1000 + i * 100) for i, t in enumerate(topics)]

    # A filter and a seek take effect from where the reader stands.
    reader = open_reader(bag)
    reader.set_filter(rosbag2_py.StorageFilter(topics=['/b']))
    assert reader.read_next()[2] == 1100
    reader.reset_filter()
    assert reader.read_next()[0::2] == ('/a', 1200)
    reader.seek(1650)
    assert [s for _, _, s in read_all(reader)] == [1700, 1800, 1900]
    with pytest.raises(RuntimeError, match='No next message'):
        reader.read_next()

    definitions = reader.get_all_message_definitions()
    assert [(d.topic_type, d.encoding) for d in definitions] == [
        ('std_msgs/msg/String', 'ros2msg')]
    assert 'string data' in definitions[0].encoded_message_definition

    metadata = rosbag2_py.Info().read_metadata(str(bag), storage_id)
    assert (metadata.message_count, metadata.storage_identifier) == (10, storage_id)
    assert metadata.duration.nanoseconds == 900
    assert metadata.compression_mode == compression.upper()
    assert [(t.topic_metadata.name, t.message_count)
            for t in metadata.topics_with_message_count] == [('/a', 5), ('/b', 5)]
    assert 'Messages:          10\n' in str(metadata)


def test_mcap_library_and_ros2_bag_read_a_rosbag2_py_bag(tmp_path, ros_env):
    from mcap.reader import make_reader
    from mcap_ros2.decoder import DecoderFactory

    bag = tmp_path / 'bag'
    write_bag(bag, 'mcap')
    with open(bag / 'bag_0.mcap', 'rb') as stream:
        reader = make_reader(stream, decoder_factories=[DecoderFactory()])
        decoded = [(c.topic, m.log_time, d.data) for _, c, m, d in
                   reader.iter_decoded_messages()]
    assert decoded[:2] == [('/a', 1000, '/a 0'), ('/b', 1100, '/b 1')] and len(decoded) == 10
    info = ros2(ros_env, 'bag', 'info', str(bag))
    assert info.returncode == 0, info
    assert 'Topic: /a | Type: std_msgs/msg/String | Count: 5 | Serialization Format: cdr' in \
        info.stdout


def test_ros2_bag_record_is_read_by_rosbag2_py_and_rosbag2_py_bag_is_played(
        tmp_path, ros_env, probe, launch):
    talker = probe.node.create_publisher(String, '/talk', 10)
    bag = tmp_path / 'recorded'
    recorder = launch(argv=['ros2', 'bag', 'record', '--disable-keyboard-controls', '-s',
                            'sqlite3', '-o', str(bag), '/talk'])
    recorder.wait_for_output('All requested topics are subscribed')
    probe.spin_until(lambda: talker.get_subscription_count() == 1, 10, 'the recorder')
    for i in range(3):
        talker.publish(String(data=f'said {i}'))
    probe.spin_for(0.5)
    assert recorder.stop() == 0
    assert [(t, d) for t, d, _ in read_all(open_reader(bag))] == [
        ('/talk', f'said {i}') for i in range(3)]

    written = tmp_path / 'written'
    write_bag(written, 'mcap')
    heard = probe.collect(String, '/b')
    with Background(probe):
        played = ros2(ros_env, 'bag', 'play', str(written), '--topics', '/b', timeout=30)
        assert played.returncode == 0, played
        wait_until(lambda: len(heard) == 5, 5, f'the played /b messages ({heard}, {played})')
    assert [m.data for m in heard] == [f'/b {i}' for i in (1, 3, 5, 7, 9)]


def digest(path: Path) -> str:
    return ''.join(hashlib.sha256(p.read_bytes()).hexdigest()
                   for p in sorted(path.rglob('*')) if p.is_file())


def test_bad_input_is_one_line_and_leaves_the_bag_intact(tmp_path, ros_env):
    bag = tmp_path / 'bag'
    write_bag(bag, 'mcap')
    before = digest(bag)
    writer = rosbag2_py.SequentialWriter()
    with pytest.raises(RuntimeError) as unknown:
        writer.open(rosbag2_py.StorageOptions(uri=str(tmp_path / 'new'), storage_id='foo'),
                    rosbag2_py.ConverterOptions('', ''))
    assert str(unknown.value) == "Unknown storage id 'foo' (allowed: mcap, sqlite3)"
    with pytest.raises(RuntimeError, match=r"Output folder '.*bag' already exists"):
        writer.open(rosbag2_py.StorageOptions(uri=str(bag)), rosbag2_py.ConverterOptions())
    with pytest.raises(RuntimeError, match="Unknown storage id 'foo'"):
        open_reader(bag, 'foo')
    with pytest.raises(RuntimeError, match=r"Bag '.*missing' does not exist"):
        open_reader(tmp_path / 'missing')
    assert digest(bag) == before

    missing = ros2(ros_env, 'bag', 'info', str(tmp_path / 'missing'))
    assert (missing.stdout, missing.returncode) == ('', 1)
    assert missing.stderr == f"[ERROR] [ros2bag]: Bag '{tmp_path / 'missing'}' does not exist\n"
    existing = ros2(ros_env, 'bag', 'record', '-a', '-o', str(bag))
    assert existing.stderr == f"[ERROR] [ros2bag]: Output folder '{bag}' already exists.\n"
    storage = ros2(ros_env, 'bag', 'record', '-a', '-s', 'foo', '-o', str(tmp_path / 'x'))
    assert storage.returncode == 2 and "argument -s/--storage: invalid choice: 'foo'" in \
        storage.stderr
    assert digest(bag) == before and not (tmp_path / 'x').exists()


@pytest.mark.parametrize('storage_id', ['mcap', 'sqlite3'])
def test_reindexer_rebuilds_the_metadata(tmp_path, storage_id):
    bag = tmp_path / 'bag'
    write_bag(bag, storage_id)
    (bag / 'metadata.yaml').unlink()
    rosbag2_py.Reindexer().reindex(rosbag2_py.StorageOptions(uri=str(bag)))
    metadata = rosbag2_py.MetadataIo().read_metadata(str(bag))
    assert (metadata.message_count, metadata.storage_identifier) == (10, storage_id)
    assert [(t.topic_metadata.name, t.message_count)
            for t in metadata.topics_with_message_count] == [('/a', 5), ('/b', 5)]
    assert len(read_all(open_reader(bag))) == 10


def test_recorder_and_player_run_in_a_thread_and_cancel(tmp_path, ros_env, probe, monkeypatch):
    for name in ('ROS_DOMAIN_ID', 'ROS_AUTOMATIC_DISCOVERY_RANGE'):
        monkeypatch.setenv(name, ros_env[name])
    talker = probe.node.create_publisher(String, '/thread_talk', 10)
    options = rosbag2_py.RecordOptions()
    options.topics = ['/thread_talk']
    options.topic_polling_interval = datetime.timedelta(milliseconds=50)
    bag = tmp_path / 'threaded'
    recording = threading.Thread(target=rosbag2_py.Recorder().record, args=(
        rosbag2_py.StorageOptions(uri=str(bag), storage_id='mcap'), options))
    recording.start()
    probe.spin_until(lambda: talker.get_subscription_count() == 1, 10, 'the recorder')
    talker.publish(String(data='in a thread'))
    probe.spin_for(0.5)
    rosbag2_py.Recorder.cancel()
    recording.join(timeout=10)
    assert not recording.is_alive()
    assert [(t, d) for t, d, _ in read_all(open_reader(bag))] == [('/thread_talk', 'in a thread')]

    play = rosbag2_py.PlayOptions()
    play.loop = True
    play.topic_remapping_options = ['--ros-args', '--remap', '/thread_talk:=/replayed']
    heard = probe.collect(String, '/replayed')
    playing = threading.Thread(target=rosbag2_py.Player().play, args=(
        rosbag2_py.StorageOptions(uri=str(bag)), play))
    playing.start()
    probe.spin_until(lambda: len(heard) >= 2, 15, 'the looped message twice')
    rosbag2_py.Player.cancel()
    playing.join(timeout=10)
    assert not playing.is_alive() and heard[0].data == 'in a thread'
    with pytest.raises(RuntimeError, match="Invalid log level 'loud'"):
        rosbag2_py.Player('loud')


def test_definitions_of_interfaces_written_in_idl():
    """rosbag2_test_msgdefs (built by rosidl here): a type with no .msg file, or depending on
    one, is defined from .idl files (ros2idl, the .msg's generated .idl); a service's
    dependency without .msg is appended as IDL; .msg on .msg stays ros2msg (Jazzy's source)."""
    rule = '=' * 80 + '\n'
    basic = ('module rosbag2_test_msgdefs {\n  module msg {\n    struct BasicIdl {\n'
             '        float x;\n    };\n  };\n};\n')
    source = rosbag2_py.LocalMessageDefinitionSource()

    found = source.get_full_text('rosbag2_test_msgdefs/msg/ComplexMsgDependsOnIdl')
    assert found.encoding == 'ros2idl', found.encoded_message_definition
    first, second = found.encoded_message_definition.split(f'\n{rule}')
    assert first.startswith(f'{rule}IDL: rosbag2_test_msgdefs/msg/ComplexMsgDependsOnIdl\n'
                            '// generated from rosidl_adapter/resource/msg.idl.em\n')
    assert '      rosbag2_test_msgdefs::msg::BasicIdl a;\n' in first
    assert second == f'IDL: rosbag2_test_msgdefs/msg/BasicIdl\n{basic}'

    found = source.get_full_text('rosbag2_test_msgdefs/srv/ComplexSrvIdl')
    assert (found.encoding, found.encoded_message_definition) == (
        'ros2idl', f'{rule}SRV: rosbag2_test_msgdefs/srv/ComplexSrvIdl\n'
        'rosbag2_test_msgdefs/BasicIdl req\n---\nrosbag2_test_msgdefs/BasicIdl resp\n\n'
        f'{rule}MSG: rosbag2_test_msgdefs/BasicIdl\n\n'
        f'{rule}IDL: rosbag2_test_msgdefs/BasicIdl\n{basic}')
    found = source.get_full_text('rosbag2_test_msgdefs/ComplexMsg')  # .msg files as before
    assert (found.encoding, found.encoded_message_definition) == (
        'ros2msg', f'rosbag2_test_msgdefs/BasicMsg b\n\n{rule}'
        'MSG: rosbag2_test_msgdefs/BasicMsg\nfloat32 c\n')
    found = source.get_full_text('no_such_pkg/msg/X')
    assert (found.encoding, found.encoded_message_definition) == ('unknown', '')


def compressing_writer(path: Path, mode: str, queue_size: int, threads: int):
    writer = rosbag2_py.SequentialCompressionWriter(rosbag2_py.CompressionOptions(
        compression_format='zstd', compression_mode=rosbag2_py.compression_mode_from_string(mode),
        compression_queue_size=queue_size, compression_threads=threads))
    writer.open(rosbag2_py.StorageOptions(uri=str(path), storage_id='mcap'),
                rosbag2_py.ConverterOptions('cdr', 'cdr'))
    writer.create_topic(rosbag2_py.TopicMetadata(
        id=0, name='/big', type='std_msgs/msg/String', serialization_format='cdr'))
    return writer


def test_compression_queue_size_and_threads_take_effect(tmp_path):
    """A queue of 1 drops what one compression thread cannot keep up with; a queue of 0
    drops nothing; in FILE mode a file is compressed as soon as a split closes it."""
    messages = [serialize_message(String(data=f'{i} ' + 'payload ' * 40_000)) for i in range(300)]
    counts = {}
    for queue_size, threads in ((1, 1), (0, 2)):
        bag = tmp_path / f'queue_{queue_size}'
        writer = compressing_writer(bag, 'message', queue_size, threads)
        for i, data in enumerate(messages):
            writer.write('/big', data, 1000 + i)
        writer.close()
        counts[queue_size] = rosbag2_py.Info().read_metadata(str(bag), '').message_count
    assert counts[0] == 300 and 0 < counts[1] < 300, counts

    bag = tmp_path / 'files'
    writer = compressing_writer(bag, 'file', 1, 1)
    writer.write('/big', messages[0], 1000)
    writer.split_bagfile()
    # The original goes once its .zstd is complete.
    wait_until(lambda: not (bag / 'files_0.mcap').exists(), 10,
               'the closed file compressed while the bag is still open')
    assert (bag / 'files_0.mcap.zstd').is_file()
    writer.write('/big', messages[1], 2000)
    writer.close()
    metadata = rosbag2_py.Info().read_metadata(str(bag), '')
    assert metadata.relative_file_paths == ['files_0.mcap.zstd', 'files_1.mcap.zstd']
    assert [s for _, _, s in read_all(open_reader(bag))] == [1000, 2000]
