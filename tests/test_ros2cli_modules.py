"""Upstream ros2cli's importable modules (`ros2cli.node.strategy`, `.direct`, `.daemon`) and
`ros2pkg.api`, as a third-party tool uses them, against a real node and our daemon.

The script runs in a process of its own (DirectNode initialises rclpy's default context, as
upstream's does) and prints what a tool would see, one line per question.
"""

from __future__ import annotations

import subprocess
import sys

from support import cli_test_node_argv

TOOL = r'''
import argparse, os
from ros2cli.node.daemon import DaemonNode, is_daemon_running, shutdown_daemon
from ros2cli.node.direct import DirectNode
from ros2cli.node.strategy import NodeStrategy, add_arguments
from ros2pkg.api import PackageNotFound, get_executable_paths, get_package_names, get_prefix_path

parser = argparse.ArgumentParser()
add_arguments(parser)
print(sorted(vars(parser.parse_args([])).items()))
args = parser.parse_args(['--spin-time', '10'])
print('running before', is_daemon_running(args))
with NodeStrategy(args) as node:  # no daemon: a node of its own, and the daemon for next time
    print('direct', node.daemon_node is None, ('cli_test_node', '/') in
          node.get_node_names_and_namespaces())
print('running after', is_daemon_running(args))
with NodeStrategy(args) as node:
    print('daemon', node.daemon_node is not None, 'daemon' in node.get_name(),
          node.get_namespace())
    print(['/pose', ['turtlesim/msg/Pose']] in node.get_topic_names_and_types(),
          ['/flag', ['std_srvs/srv/SetBool']] in node.get_service_names_and_types(),
          ['cli_test_node', '/', '/'] in node.get_node_names_and_namespaces_with_enclaves())
    print('counts', node.count_publishers('/pose'), node.count_subscribers('/heard'),
          node.count_services('/flag'), node.count_clients('/flag'))
    print(node.get_subscriber_names_and_types_by_node('cli_test_node', '/'),
          ['/flag', ['std_srvs/srv/SetBool']] in
          node.get_service_names_and_types_by_node('cli_test_node', '/'))
    print([(i.node_name, i.node_namespace, i.topic_type, i.endpoint_type.name,
            i.qos_profile.reliability.name, i.qos_profile.durability.name)
           for i in node.get_publishers_info_by_topic('/pose')])
    print(node._direct_node is None)  # all answered by the daemon so far
    # What the daemon does not answer comes from a node of its own, made on first use.
    print('direct', node.get_fully_qualified_name().startswith('/_ros2cli_'))
with NodeStrategy(argparse.Namespace(no_daemon=True)) as node:
    print('no daemon', node.daemon_node is None)
with DirectNode(argparse.Namespace(use_sim_time=True, spin_time=0.1)) as node:
    print('sim time', node.node.get_parameter('use_sim_time').value)
with DaemonNode(args) as daemon:
    print('connected', daemon.connected)
print('shutdown', shutdown_daemon(args, timeout=10), is_daemon_running(args),
      shutdown_daemon(args))
print('ros2cli' in get_package_names(), os.path.isdir(get_prefix_path('ros2cli')),
      get_prefix_path('invalid.package.name'), get_prefix_path('no_such_package'))
print([os.path.basename(p) for p in get_executable_paths(package_name='turtlesim')
       if p.endswith('turtlesim_node')])
try:
    get_executable_paths(package_name='no_such_package')
except PackageNotFound as error:
    print('not found', error.package_name)
'''

EXPECTED = '''\
[('no_daemon', False), ('spin_time', 0.5), ('use_sim_time', False)]
running before False
direct True True
running after True
daemon True True /
True True True
counts 1 1 1 0
[['/heard', ['std_msgs/msg/String']]] True
[('cli_test_node', '/', 'turtlesim/msg/Pose', 'PUBLISHER', 'RELIABLE', 'VOLATILE')]
True
direct True
no daemon True
sim time True
connected True
shutdown True False False
True True None None
['turtlesim_node']
not found no_such_package
'''


def test_node_strategy_direct_and_daemon_nodes(ros_env, launch):
    node = launch(argv=cli_test_node_argv())
    node.wait_for_output('^READY$')
    result = subprocess.run([sys.executable, '-c', TOOL], env=ros_env, capture_output=True,
                            text=True, timeout=60, stdin=subprocess.DEVNULL)
    assert (result.stdout, result.returncode) == (EXPECTED, 0), result.stderr
