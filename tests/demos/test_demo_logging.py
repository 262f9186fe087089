""""Logging" (Jazzy Demos), typed as the page says: `ros2 run logging_demo logging_demo_main`
(once-only line, DEBUG after 5.5 s), `/config_logger` (and a bad level refused), the logger
services of a node made with `enable_logger_service=True`, `--log-level` for all loggers and
for one, RCUTILS_CONSOLE_OUTPUT_FORMAT and RCUTILS_COLORIZED_OUTPUT."""
from __future__ import annotations

import re
import sys

from support import ros2

DEMO = ['ros2', 'run', 'logging_demo', 'logging_demo_main']
TIME = r'\[[\d.]+\]'
# The page's snippet, as a learner would put it in a file of their own.
NODE_WITH_LOGGER_SERVICE = '''
import rclpy
from rclpy.node import Node

rclpy.init()
# Create a node with logger service enabled
node = Node('NodeWithLoggerService', enable_logger_service=True)
try:
    rclpy.spin(node)
except KeyboardInterrupt:
    pass
'''


def test_demo_config_logger_and_its_errors(ros_env, launch) -> None:
    demo = launch(argv=DEMO)
    demo.wait_for_output(rf"^\[INFO\] {TIME} \[logger_usage_demo\]: Publishing: 'Current count: "
                         r"0'$", timeout=20)
    demo.wait_for_output(rf'^\[INFO\] {TIME} \[logger_usage_demo\]: Setting severity threshold '
                         rf'to DEBUG\n(?:.*\n)*\[DEBUG\] {TIME} \[logger_usage_demo\]: Count is '
                         r'even \(expression evaluated to true\)$', timeout=20)
    assert demo.output.count('Timer callback called (this will only log once)') == 1
    assert '[DEBUG]' not in demo.output.split('Setting severity threshold to DEBUG')[0]

    bad = ros2(ros_env, 'service', 'call', '/config_logger', 'logging_demo/srv/ConfigLogger',
               "{logger_name: '', level: LOUD}")
    assert bad.stdout.endswith('response:\nlogging_demo.srv.ConfigLogger_Response('
                               'success=False)\n\n'), bad
    demo.wait_for_output(rf"^\[ERROR\] {TIME} \[logger_config\]: Unknown severity 'LOUD'$")
    assert '[rcl]' not in demo.output  # nothing changed

    good = ros2(ros_env, 'service', 'call', '/config_logger', 'logging_demo/srv/ConfigLogger',
                "{logger_name: '', level: DEBUG}")
    assert good.stdout.endswith('logging_demo.srv.ConfigLogger_Response(success=True)\n\n')
    demo.wait_for_output(rf"^\[INFO\] {TIME} \[logger_config\]: Incoming request: logger '', "
                         r"severity 'DEBUG'$")
    # The ROS 2 core's loggers were unset: their debug output appears.
    demo.wait_for_output(rf'^\[DEBUG\] {TIME} \[rcl\]: ', timeout=10)
    assert demo.stop() == 0


def test_node_with_logger_service(ros_env, launch, tmp_path) -> None:
    script = tmp_path / 'node_with_logger_service.py'
    script.write_text(NODE_WITH_LOGGER_SERVICE)
    node = launch(argv=[sys.executable, str(script)])
    get = ros2(ros_env, 'service', 'call', '/NodeWithLoggerService/get_logger_levels',
               'rcl_interfaces/srv/GetLoggerLevels', '{names: ["NodeWithLoggerService", "rcl"]}')
    assert get.stdout.endswith(
        "requester: making request: rcl_interfaces.srv.GetLoggerLevels_Request(names=["
        "'NodeWithLoggerService', 'rcl'])\n\nresponse:\nrcl_interfaces.srv.GetLoggerLevels_"
        "Response(levels=[rcl_interfaces.msg.LoggerLevel(name='NodeWithLoggerService', "
        "level=0), rcl_interfaces.msg.LoggerLevel(name='rcl', level=0)])\n\n"), get
    listed = ros2(ros_env, 'service', 'list').stdout.splitlines()
    assert {'/NodeWithLoggerService/get_logger_levels',
            '/NodeWithLoggerService/set_logger_levels'} <= set(listed)
    set_ = ros2(ros_env, 'service', 'call', '/NodeWithLoggerService/set_logger_levels',
                'rcl_interfaces/srv/SetLoggerLevels',
                '{levels: [{name: "NodeWithLoggerService", level: 20}, '
                '{name: "rcl", level: 10}]}')
    assert set_.stdout.endswith(
        'response:\nrcl_interfaces.srv.SetLoggerLevels_Response(results=[rcl_interfaces.msg.'
        "SetLoggerLevelsResult(successful=True, reason=''), rcl_interfaces.msg."
        "SetLoggerLevelsResult(successful=True, reason='')])\n\n"), set_
    # A level that is no severity is refused, and the level stays.
    bad = ros2(ros_env, 'service', 'call', '/NodeWithLoggerService/set_logger_levels',
               'rcl_interfaces/srv/SetLoggerLevels',
               '{levels: [{name: "NodeWithLoggerService", level: 15}]}')
    assert 'successful=False' in bad.stdout, bad
    after = ros2(ros_env, 'service', 'call', '/NodeWithLoggerService/get_logger_levels',
                 'rcl_interfaces/srv/GetLoggerLevels', '{names: ["NodeWithLoggerService"]}')
    assert "LoggerLevel(name='NodeWithLoggerService', level=20)" in after.stdout, after
    assert node.stop() == 0


def test_log_level_on_the_command_line(launch, ros_env, tmp_path) -> None:
    # The page's last step: the log file's name prefix, in ROS_LOG_DIR.
    talker = launch(argv=['ros2', 'run', 'demo_nodes_cpp', 'talker', '--ros-args',
                          '--log-file-name', 'filename'],
                    env={**ros_env, 'ROS_LOG_DIR': str(tmp_path)})
    everything = launch(argv=[*DEMO, '--ros-args', '--log-level', 'debug'])
    everything.wait_for_output(rf'^\[DEBUG\] {TIME} \[rcl\]: ', timeout=20)
    everything.wait_for_output(rf'^\[DEBUG\] {TIME} \[logger_usage_demo\]: Count is even')
    assert everything.stop() == 0
    one = launch(argv=[*DEMO, '--ros-args', '--log-level', 'logger_usage_demo:=debug'])
    one.wait_for_output(rf'^\[DEBUG\] {TIME} \[logger_usage_demo\]: Count is even', timeout=20)
    assert 'Setting severity threshold' not in one.output  # debug before the 5.5 s timer
    assert '[rcl]' not in one.output
    assert one.stop() == 0
    talker.wait_for_output(r"Publishing: 'Hello World: 1'")
    assert talker.stop() == 0
    files = list(tmp_path.glob('filename_*.log'))
    assert len(files) == 1, list(tmp_path.iterdir())
    assert "[talker]: Publishing: 'Hello World: 1'" in files[0].read_text()


def test_bad_log_level_is_refused(launch) -> None:
    bad = launch(argv=[*DEMO, '--ros-args', '--log-level', 'logger_usage_demo:=loud'])
    assert bad.wait(timeout=20) == 1
    # rcl's own error line, its reason (no traceback), and ros2 run's exit line.
    lines = bad.output.splitlines()
    assert len(lines) == 3, bad.output
    assert re.match(rf'\[ERROR\] {TIME} \[rcl\]: Failed to parse global arguments$', lines[0])
    assert lines[1:] == [
        "failed to initialize rcl: Couldn't parse log level: '--log-level logger_usage_demo:=loud'."
        ' Error: Argument does not use a valid severity level',
        '[ros2run]: Process exited with failure 1']


def test_output_format_and_colours(launch, ros_env) -> None:
    formatted = launch(argv=DEMO, env={
        **ros_env, 'RCUTILS_CONSOLE_OUTPUT_FORMAT':
            '[{severity} {time}] [{name}]: {message} ({function_name}() at '
            '{file_name}:{line_number})'})
    formatted.wait_for_output(r"^\[INFO [\d.]+\] \[logger_usage_demo\]: Publishing: 'Current "
                              r"count: 0' \(on_timer\(\) at \S+logger_usage\.py:\d+\)$",
                              timeout=20)
    coloured = launch(argv=DEMO, env={**ros_env, 'RCUTILS_COLORIZED_OUTPUT': '1'})
    # rcutils wraps each line in its colour (INFO: the terminal's normal one).
    coloured.wait_for_output(rf"^\x1b\[0m\[INFO\] {TIME} \[logger_usage_demo\]: Publishing: "
                             r"'Current count: 0'\x1b\[0m$", timeout=20)
    plain = launch(argv=DEMO, env={**ros_env, 'RCUTILS_COLORIZED_OUTPUT': '0'})
    plain.wait_for_output(r'Publishing', timeout=20)
    for process in (formatted, coloured, plain):
        assert process.stop() == 0
    assert '\x1b[' not in plain.output
    assert not re.search(r'\x1b', formatted.output)
