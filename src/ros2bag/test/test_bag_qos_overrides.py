"""How-to "rosbag2: Overriding QoS Policies", typed as written; invalid override files."""

from __future__ import annotations

import re
import signal

from rclpy.qos import DurabilityPolicy, QoSProfile
from std_msgs.msg import String

from ws_testing import ros2

DURABILITY_OVERRIDE = """\
# durability_override.yaml
/talker:
  durability: transient_local
  history: keep_all
"""
RELIABILITY_OVERRIDE = """\
# reliability_override.yaml
/talker:
  reliability: best_effort
  history: keep_all
"""


def test_the_page_records_a_latched_topic_and_plays_it_best_effort(launch, ros_env, tmp_path,
                                                                   probe):
    (tmp_path / 'durability_override.yaml').write_text(DURABILITY_OVERRIDE)
    (tmp_path / 'reliability_override.yaml').write_text(RELIABILITY_OVERRIDE)
    talker = launch(argv=['ros2', 'topic', 'pub', '-r', '0.1', '--qos-durability',
                          'transient_local', '/talker', 'std_msgs/String', 'data: Hello World'])
    talker.wait_for_output('publishing #1')
    bag = tmp_path / 'my_bag'
    recorder = launch(argv=['ros2', 'bag', 'record', '-a', '-o', str(bag),
                            '--qos-profile-overrides-path',
                            str(tmp_path / 'durability_override.yaml')])
    recorder.wait_for_output(r'\[rosbag2_recorder\]: Overriding subscription profile for '
                             r'/talker\n')
    recorder.wait_for_output(r"Subscribed to topic '/talker'")
    # The one message sent before the recorder came is delivered to it as a late joiner, once
    # the talker has discovered the recorder's subscription. A transient-local subscription of
    # the probe made after it has its copy once that discovery has run its course (the talker
    # stays up meanwhile, as on the page).
    latched = probe.collect(String, '/talker', QoSProfile(
        depth=1, durability=DurabilityPolicy.TRANSIENT_LOCAL))
    probe.spin_until(lambda: latched, 15, "the talker's latched message")
    probe.spin_for(0.5)
    recorder.popen.send_signal(signal.SIGINT)
    assert recorder.popen.wait(timeout=15) == 0
    talker.stop()
    info = ros2(ros_env, 'bag', 'info', str(bag))
    assert re.search(r'Topic: /talker \| Type: std_msgs/msg/String \| Count: 1 \|', info.stdout), \
        info

    echo = launch(argv=['ros2', 'topic', 'echo', '--qos-reliability', 'best_effort', '/talker',
                        'std_msgs/String'])
    probe.spin_until(lambda: probe.node.count_subscribers('/talker') == 1, 15,
                     "the echo's subscription")
    played = ros2(ros_env, 'bag', 'play', '--qos-profile-overrides-path',
                  str(tmp_path / 'reliability_override.yaml'), str(bag), timeout=30)
    assert played.returncode == 0, played
    echo.wait_for_output(r'data: Hello World\n---\n')


def test_an_invalid_override_file_is_one_line_and_no_bag(ros_env, tmp_path):
    cases = {
        'duration.yaml': ('/talker:\n  history: keep_all\n  deadline:\n    sec: 2\n',
                          'Time overrides must include both seconds (sec) and nanoseconds '
                          '(nsec).'),
        'policy.yaml': ('/talker:\n  history: keep_all\n  durability: forever\n',
                        "Invalid value 'forever' for QoS policy 'durability' (allowed: "
                        'system_default, transient_local, volatile, unknown, best_available)'),
        'key.yaml': ('/talker:\n  history: keep_all\n  durabilty: volatile\n',
                     'Unexpected key `durabilty` for QoS profile.'),
        'yaml.yaml': ('/talker: [history: keep_all\n', "is not valid YAML (line 2)"),
    }
    for name, (text, message) in cases.items():
        (tmp_path / name).write_text(text)
        # record reads the file as play does (ros2bag.api): play is checked with one case
        verbs = [['record', '-a', '-o', str(tmp_path / 'never')]]
        if name == 'policy.yaml':
            verbs.append(['play', str(tmp_path)])
        for verb in verbs:
            result = ros2(ros_env, 'bag', *verb, '--qos-profile-overrides-path',
                          str(tmp_path / name))
            assert result.returncode == 1 and result.stdout == '', result
            assert result.stderr.count('\n') == 1 and result.stderr.startswith(
                '[ERROR] [ros2bag]: ') and message in result.stderr, result
    missing = ros2(ros_env, 'bag', 'record', '-a', '--qos-profile-overrides-path',
                   str(tmp_path / 'foobar.yaml'))
    assert missing.returncode == 2 and re.search(
        r"ros2 bag record: error: argument --qos-profile-overrides-path: can't open",
        missing.stderr)
    assert not (tmp_path / 'never').exists()
