""""Using ROS 2 launch for large projects" starts rviz2 from a launch file without
output='screen': `ros2 launch` keeps such a node's stdout in its log file, so rviz2 and the rqt
tools also say their page's URL through the ROS logger, whose lines `ros2 launch` shows; and
they open the browser the user configured ($BROWSER)."""

from __future__ import annotations

import subprocess

LAUNCH_FILE = '''\
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='rviz2', executable='rviz2', name='rviz2'),
        Node(package='rqt_graph', executable='rqt_graph'),
    ])
'''
URL = r'http://127\.0\.0\.1:\d+/{}\?token=\w+'


def test_launched_rviz2_and_rqt_graph_tell_their_urls(launch, ros_env, tmp_path) -> None:
    (tmp_path / 'web_tools_launch.py').write_text(LAUNCH_FILE)
    opened = tmp_path / 'opened.txt'
    browser = tmp_path / 'browser'
    browser.write_text(f'#!/bin/sh\necho "$1" >> {opened}\n')
    browser.chmod(0o755)
    env = {**ros_env, 'BROWSER': str(browser)}
    env.pop('DISPLAY', None)
    try:
        demo = launch(argv=['ros2', 'launch', str(tmp_path / 'web_tools_launch.py')], env=env)
        rviz = demo.wait_for_output(
            r'^\[rviz2-1\] \[INFO\] \[\d+\.\d+\] \[rviz2\]: RViz: (' + URL.format('rviz')
            + ')', timeout=30)
        graph = demo.wait_for_output(
            r'^\[rqt_graph-2\] \[INFO\] \[\d+\.\d+\] \[rqt_graph\]: Node Graph: ('
            + URL.format('graph') + ')', timeout=30)
        demo.wait_for_output(r'\[rqt_graph-2\]: process has finished cleanly')
        demo.wait_for_output(r'\[rviz2-1\]: process has finished cleanly')
        # The stdout line stays in the log file only (output='log'), as upstream's launch does.
        assert 'rviz2: RViz:' not in demo.output
        assert sorted(opened.read_text().split()) == sorted([graph[1], rviz[1].split()[0]])
        assert 'Traceback' not in demo.output
    finally:
        subprocess.run(['rqt', '--stop'], env=env, capture_output=True, timeout=20)
