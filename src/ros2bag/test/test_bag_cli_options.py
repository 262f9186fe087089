"""ros2bag's module layout and record options as upstream's: `ros2bag.api`,
`ros2bag.verb.record`, --log-level, --compression-*, the storage presets, `burst`; and bags of
older metadata versions read by rosbag2_py."""

from __future__ import annotations

import argparse
import re
import signal

import pytest
import yaml
from rclpy.qos import HistoryPolicy, QoSProfile
from rclpy.serialization import serialize_message
from ros2bag.api import convert_yaml_to_qos_profile, dict_to_duration, interpret_dict_as_qos_profile
from ros2bag.verb.record import add_recorder_arguments, validate_parsed_arguments
from std_msgs.msg import String

import rosbag2_py
from ws_testing import Background, ros2, wait_until


def test_qos_override_api():
    assert dict_to_duration({'sec': 1, 'nsec': 2}).nanoseconds == 1_000_000_002
    with pytest.raises(ValueError, match='must include both seconds'):
        dict_to_duration({'sec': 1})
    for bad in ({'history': 'keep_all', 'depth': -1}, {'foo': 'bar'},
                {'history': 'keep_all', 'lifespan': {'sec': -1, 'nsec': -1}}):
        with pytest.raises(ValueError):
            interpret_dict_as_qos_profile(bad)
    profiles = convert_yaml_to_qos_profile({'/t': {'history': 'keep_all', 'depth': 3}})
    assert (profiles['/t'].history, profiles['/t'].depth) == (HistoryPolicy.KEEP_ALL, 3)


def test_recorder_arguments_and_their_checks(tmp_path):
    parser = argparse.ArgumentParser()
    add_recorder_arguments(parser)
    args = parser.parse_args(['--topic-types', 'std_msgs/msg/String', '--exclude-topic-types',
                              'a/msg/B', '--output', str(tmp_path / 'out')])
    assert (args.topic_types, args.exclude_topic_types) == (['std_msgs/msg/String'],
                                                            ['a/msg/B'])
    assert validate_parsed_arguments(args, args.output) == (
        '[ERROR] [ros2bag]: --exclude-topic-types argument requires either --all, '
        '--all-topics or --regex')
    args = parser.parse_args(['--exclude-regex', 'x', '--topics', 't'])
    assert validate_parsed_arguments(args, str(tmp_path / 'o')) == (
        '[ERROR] [ros2bag]: --exclude-regex argument requires either --all, --all-topics, '
        '--topic-types, --all-services or --regex')


def test_help_lists_each_storages_presets(ros_env, tmp_path):
    shown = ros2(ros_env, 'bag', 'record', '-s', 'mcap', '--help')
    assert shown.returncode == 0
    assert re.search(r'mcap: fastwrite, zstd_fast, zstd_small\n\s+sqlite3: resilient\n',
                     shown.stdout), shown.stdout
    refused = ros2(ros_env, 'bag', 'record', '-a', '--storage-preset-profile', 'resilient',
                   '-o', str(tmp_path / 'never'))
    assert refused.stderr == ("[ERROR] [ros2bag]: Unknown storage preset profile 'resilient' "
                              'for mcap (allowed: fastwrite, zstd_fast, zstd_small)\n')
    assert not (tmp_path / 'never').exists()


def test_file_compression_at_a_thread_priority_with_debug_logs(launch, probe, ros_env,
                                                               tmp_path):
    talker = probe.node.create_publisher(String, '/squeezed', 10)
    bag = tmp_path / 'compressed'
    recorder = launch(argv=['ros2', 'bag', 'record', '--topics', '/squeezed', '-o', str(bag),
                            '--log-level', 'debug', '--compression-threads-priority', '1',
                            '--compression-mode', 'file', '--compression-format', 'zstd'])
    recorder.wait_for_output(r'\[DEBUG\] \[[\d.]+\] \[rosbag2_recorder\]: Setting compression '
                             r'thread priority to 1\n')
    recorder.wait_for_output('All requested topics are subscribed')
    probe.spin_until(lambda: talker.get_subscription_count() == 1, 10, 'the recorder')
    talker.publish(String(data='small'))
    probe.spin_for(0.3)
    recorder.popen.send_signal(signal.SIGINT)
    assert recorder.popen.wait(timeout=15) == 0
    assert sorted(p.name for p in bag.iterdir()) == ['compressed_0.mcap.zstd', 'metadata.yaml']
    metadata = rosbag2_py.Info().read_metadata(str(bag), 'mcap')
    assert (metadata.compression_mode, metadata.compression_format) == ('FILE', 'zstd')
    reader = rosbag2_py.SequentialReader()
    reader.open_uri(str(bag))
    assert reader.read_next()[0] == '/squeezed' and not reader.has_next()


def test_an_older_bag_is_read_and_burst(tmp_path, ros_env, probe):
    """Metadata version 4 spells QoS policies as integers in a string: the storage file's
    topics are still read (rosbags alone matched them against metadata.yaml's and found no
    message at all in Jazzy's own test bags)."""
    bag = tmp_path / 'old'
    writer = rosbag2_py.SequentialWriter()
    writer.open(rosbag2_py.StorageOptions(uri=str(bag), storage_id='sqlite3'),
                rosbag2_py.ConverterOptions())
    writer.create_topic(rosbag2_py.TopicMetadata(
        0, '/old', 'std_msgs/msg/String', 'cdr', [QoSProfile(depth=10)]))
    for i in range(3):
        writer.write('/old', serialize_message(String(data=f'old {i}')), 10 + i)
    writer.close()
    path = bag / 'metadata.yaml'
    document = yaml.safe_load(path.read_text())
    info = document['rosbag2_bagfile_information']
    info['version'] = 4
    topic = info['topics_with_message_count'][0]['topic_metadata']
    topic['offered_qos_profiles'] = ('- history: 3\n  depth: 0\n  reliability: 1\n'
                                     '  durability: 2\n  deadline:\n    sec: 0\n    nsec: 0\n'
                                     '  lifespan:\n    sec: 0\n    nsec: 0\n  liveliness: 1\n'
                                     '  liveliness_lease_duration:\n    sec: 0\n    nsec: 0\n'
                                     '  avoid_ros_namespace_conventions: false')
    path.write_text(yaml.safe_dump(document))
    reader = rosbag2_py.SequentialReader()
    reader.open_uri(str(bag))
    stamps = []
    while reader.has_next():
        stamps.append(reader.read_next()[2])
    assert stamps == [10, 11, 12]

    heard = probe.collect(String, '/old')
    with Background(probe):
        burst = ros2(ros_env, 'bag', 'burst', str(bag), timeout=30)
        wait_until(lambda: len(heard) == 3, 5, 'the burst messages')
    assert burst.returncode == 0, burst
    assert [m.data for m in heard] == ['old 0', 'old 1', 'old 2']


def test_unpublished_topics_in_and_leaf_topics_out(launch, probe, tmp_path):
    """--include-unpublished-topics subscribes to a topic only subscribers use (a publisher
    coming later is recorded); --ignore-leaf-topics leaves out one nobody subscribes to."""
    probe.collect(String, '/only_heard')
    leaf = probe.node.create_publisher(String, '/leaf', 10)
    both = probe.node.create_publisher(String, '/both', 10)
    probe.collect(String, '/both')
    bag = tmp_path / 'bag'
    recorder = launch(argv=['ros2', 'bag', 'record', '-a', '--include-unpublished-topics',
                            '--ignore-leaf-topics', '-f', 'cdr', '-o', str(bag)])
    recorder.wait_for_output(r"Subscribed to topic '/only_heard'", timeout=15)
    recorder.wait_for_output(r"Subscribed to topic '/both'")
    late = probe.node.create_publisher(String, '/only_heard', 10)
    probe.spin_until(lambda: late.get_subscription_count() == 2 and
                     both.get_subscription_count() == 2, 10, 'the recorder on both topics')
    for publisher in (late, leaf, both):
        publisher.publish(String(data='hello'))
    probe.spin_for(0.5)
    recorder.popen.send_signal(signal.SIGINT)
    assert recorder.popen.wait(timeout=15) == 0
    assert "'/leaf'" not in recorder.output
    reader = rosbag2_py.SequentialReader()
    reader.open_uri(str(bag))
    formats = {t.name: t.serialization_format for t in reader.get_all_topics_and_types()}
    assert formats['/only_heard'] == formats['/both'] == 'cdr' and '/leaf' not in formats
    heard = set()
    while reader.has_next():
        heard.add(reader.read_next()[0])
    assert heard == {'/only_heard', '/both'}
