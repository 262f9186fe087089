"""The checks and reports of `ros2 doctor`, for a pip-installed Jazzy on this machine.

Each check returns a Result (warnings and errors are printed as they are found); each report
returns a Report for `--report`. Checks and reports of one category fail together.
"""

from __future__ import annotations

import os
import platform
import re
import sys
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from ros2doctor.api import Report, Result

DISTRO = 'jazzy'
# Jazzy's entry in the rosdistro index (no network here to fetch it).
DISTRO_INFO = {
    'distribution type': 'ros2', 'distribution status': 'active',
    'release platforms': {'debian': ['bookworm'], 'rhel': ['9'], 'ubuntu': ['noble']},
}
SUPPORTED_PYTHON = ((3, 10), (3, 13))
DISCOVERY_RANGES = ('SUBNET', 'LOCALHOST', 'OFF', 'SYSTEM_DEFAULT')
MAX_DOMAIN_ID = 232
# Above 101, a domain's participant ports reach Linux's ephemeral port range (32768+).
SAFE_DOMAIN_ID = 101
SKIP_TOPICS = ('/parameter_events', '/rosout')
DISCOVERY_WINDOW = 5.0  # longest wait for the doctor's node to see what the daemon sees


# --------------------------------------------------------------------------------------
# platform
# --------------------------------------------------------------------------------------

def check_platform() -> Result:
    result = Result()
    distro = os.environ.get('ROS_DISTRO')
    if not distro:
        result.fail('ROS_DISTRO is not set.')
    elif distro != DISTRO:
        result.warn(f'ROS_DISTRO is {distro}, but the installed ROS 2 wheels are {DISTRO}.')
    if platform.system() != 'Linux' or platform.machine() != 'x86_64':
        result.fail(f'The ROS 2 {DISTRO} wheels exist for Linux x86_64 only, this is '
                    f'{platform.system()} {platform.machine()}.')
    low, high = SUPPORTED_PYTHON
    if not low <= sys.version_info[:2] <= high:
        result.warn(f'Python {platform.python_version()} is outside the {low[0]}.{low[1]} to '
                    f'{high[0]}.{high[1]} range the ROS 2 wheels are built for.')
    return result


def report_platform() -> list[Report]:
    system = Report('PLATFORM INFORMATION')
    system.add('system', platform.system())
    system.add('platform info', platform.platform())
    system.add('release', platform.release())
    system.add('processor', platform.processor() or platform.machine())
    ros = Report('ROS 2 INFORMATION')
    ros.add('distribution name', os.environ.get('ROS_DISTRO', DISTRO))
    for name, value in DISTRO_INFO.items():
        ros.add(name, value)
    return [system, ros]


# --------------------------------------------------------------------------------------
# network: interfaces and the discovery range
# --------------------------------------------------------------------------------------

def _interfaces() -> dict[str, set[str]]:
    """{interface: its flags ('up', 'loopback', 'multicast', ...)}."""
    import psutil
    return {name: set(filter(None, stats.flags.split(',')))
            for name, stats in psutil.net_if_stats().items()}


def check_network() -> Result:
    result = Result()
    interfaces = _interfaces()
    if not any('loopback' in flags for flags in interfaces.values()):
        result.fail('No loopback IP address is found.')
    if all('loopback' in flags for flags in interfaces.values()):
        result.warn('Only loopback IP address is found.')
    if not any('multicast' in flags for flags in interfaces.values()):
        result.warn('No multicast IP address is found.')
    from ros2multicast.api import loopback_delivers
    if not loopback_delivers():
        # The Installation troubleshooting page's check, done here on loopback.
        result.warn('A UDP multicast datagram sent on this machine was not received: '
                    'multicast may be blocked (firewall?). Check with `ros2 multicast '
                    'receive` and `ros2 multicast send` in two terminals.')
    scope = os.environ.get('ROS_AUTOMATIC_DISCOVERY_RANGE', '')
    if scope and scope not in DISCOVERY_RANGES:
        result.fail(f"ROS_AUTOMATIC_DISCOVERY_RANGE is '{scope}', allowed: "
                    f"{', '.join(DISCOVERY_RANGES)}.")
    elif scope in ('', 'SUBNET', 'SYSTEM_DEFAULT'):
        result.warn(f"ROS_AUTOMATIC_DISCOVERY_RANGE is {scope or 'not set (SUBNET)'}: "
                    'discovery traffic goes out of every interface; this workspace keeps it '
                    'on this machine with LOCALHOST (source scripts/env.sh).')
    if os.environ.get('ROS_LOCALHOST_ONLY'):
        result.warn('ROS_LOCALHOST_ONLY is deprecated since Jazzy: use '
                    'ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST instead.')
    return result


def report_network() -> list[Report]:
    import socket

    import psutil
    report = Report('NETWORK CONFIGURATION')
    stats = psutil.net_if_stats()
    for name, addresses in psutil.net_if_addrs().items():
        info: dict[str, Any] = {'inet': None, 'inet4': [], 'ether': None, 'inet6': [],
                                'netmask': None, 'device': name, 'flags': None, 'mtu': None,
                                'broadcast': None}
        for address in addresses:
            if address.family == socket.AF_INET:
                info['inet'] = address.address
                info['inet4'].append(address.address)
                info['netmask'] = address.netmask
                info['broadcast'] = address.broadcast
            elif address.family == socket.AF_INET6:
                info['inet6'].append(address.address)
            elif address.family == getattr(socket, 'AF_PACKET', None) \
                    and address.address != '00:00:00:00:00:00':
                info['ether'] = address.address
        if name in stats:
            info['mtu'] = stats[name].mtu
            info['flags'] = stats[name].flags.upper()
        for item, value in info.items():
            if value:
                report.add(item, value)
    report.add('ROS_AUTOMATIC_DISCOVERY_RANGE',
               os.environ.get('ROS_AUTOMATIC_DISCOVERY_RANGE') or 'not set (SUBNET)')
    report.add('ROS_STATIC_PEERS', os.environ.get('ROS_STATIC_PEERS') or 'not set')
    return [report]


# --------------------------------------------------------------------------------------
# middleware: RMW implementation and domain id
# --------------------------------------------------------------------------------------

def _bad_domain() -> bool:
    domain = os.environ.get('ROS_DOMAIN_ID', '').strip()
    return bool(domain) and (not domain.isdigit() or int(domain) > MAX_DOMAIN_ID)


def check_middleware() -> Result:
    result = Result()
    wanted = os.environ.get('RMW_IMPLEMENTATION')
    if wanted:
        from ament_index_python.packages import get_packages_with_prefixes
        if wanted not in get_packages_with_prefixes():
            result.fail(f"RMW_IMPLEMENTATION is '{wanted}', which is not installed "
                        '(installed here: rmw_fastrtps_cpp).')
    domain = os.environ.get('ROS_DOMAIN_ID', '')
    if _bad_domain():
        result.fail(f"ROS_DOMAIN_ID is '{domain}', allowed: an integer in "
                    f'[0, {MAX_DOMAIN_ID}].')
    elif domain.strip() and int(domain) > SAFE_DOMAIN_ID:
        result.warn(f'ROS_DOMAIN_ID {int(domain)} is above {SAFE_DOMAIN_ID}: its DDS ports '
                    'may collide with ephemeral ports; prefer 0 to 101.')
    return result


def report_middleware() -> list[Report]:
    from rclpy.utilities import get_rmw_implementation_identifier
    report = Report('RMW MIDDLEWARE')
    report.add('middleware name', get_rmw_implementation_identifier())
    report.add('ROS_DOMAIN_ID', os.environ.get('ROS_DOMAIN_ID') or 'not set (0)')
    return [report]


# --------------------------------------------------------------------------------------
# the running graph: topics and QoS
# --------------------------------------------------------------------------------------

@dataclass
class Graph:
    """One discovery pass, shared by the topic and QoS checks and reports."""

    topics: list[tuple[str, list[str]]] = field(default_factory=list)
    publishers: dict[str, list[Any]] = field(default_factory=dict)
    subscriptions: dict[str, list[Any]] = field(default_factory=dict)


_graph: Graph | None = None


def graph() -> Graph:
    global _graph
    if _bad_domain():
        # Fast DDS ends the whole process when asked for a participant there.
        raise RuntimeError('ROS_DOMAIN_ID is invalid')
    if _graph is None:
        from ros2cli.graph import get_graph
        from ros2cli.node.direct import cli_node
        from ros2cli.node.discovery import wait_for_graph
        from ros2cli.verb_context import VerbContext
        # The daemon's settled graph says what exists; our own node (which the QoS profiles
        # need) must then see at least every endpoint the daemon sees before it is read.
        expected = get_graph(detail=False)
        found = Graph()
        with cli_node(VerbContext.here()) as node:
            def sees_everything() -> bool:
                for name, _ in expected.topics(include_hidden=True):
                    publishers, subscribers = expected.topic_counts(name)
                    if (len(node.get_publishers_info_by_topic(name)) < publishers
                            or len(node.get_subscriptions_info_by_topic(name)) < subscribers):
                        return False
                return True
            wait_for_graph(node, ready=sees_everything, settle=0.3, bound=DISCOVERY_WINDOW)
            own = node.get_fully_qualified_name()
            for name, types in sorted(node.get_topic_names_and_types()):
                found.topics.append((name, list(types)))
                found.publishers[name] = [i for i in node.get_publishers_info_by_topic(name)
                                          if _full_name(i) != own]
                found.subscriptions[name] = [
                    i for i in node.get_subscriptions_info_by_topic(name) if _full_name(i) != own]
        _graph = found
    return _graph


def _full_name(info: Any) -> str:
    return info.node_namespace.rstrip('/') + '/' + info.node_name


def _graph_or_failure(result: Result) -> Graph | None:
    """The graph, or None with the reason as an error (e.g. rcl refused the domain id)."""
    try:
        return graph()
    except Exception as error:  # any rcl failure is a finding here, not a crash
        result.fail(f'Unable to join the ROS graph: {" ".join(str(error).split())}')
        return None


def _internal(topic: str) -> bool:
    """A node's private hidden topic (e.g. turtlesim's `~/_canvas`), which upstream nodes lack.

    Standard hidden endpoints stay: action topics (`…/_action/feedback`) and service
    introspection (`…/_service_event`) are part of what an upstream graph shows.
    """
    last = topic.rsplit('/', 1)[-1]
    return last.startswith('_') and last != '_service_event'


def check_topics() -> Result:
    result = Result()
    found = _graph_or_failure(result)
    if found is None:
        return result
    for topic, _ in found.topics:
        if topic in SKIP_TOPICS or _internal(topic):
            continue
        publishers, subscribers = len(found.publishers[topic]), len(found.subscriptions[topic])
        if publishers and not subscribers:
            result.warn(f'Publisher without subscriber detected on {topic}.')
        elif subscribers and not publishers:
            result.warn(f'Subscriber without publisher detected on {topic}.')
    return result


def report_topics() -> list[Report]:
    report = Report('TOPIC LIST')
    found = graph()
    topics = [t for t, _ in found.topics if t not in SKIP_TOPICS and not _internal(t)]
    if not topics:
        report.add('topic', 'none')
        report.add('publisher count', 0)
        report.add('subscriber count', 0)
    for topic in topics:
        report.add('topic', topic)
        report.add('publisher count', len(found.publishers[topic]))
        report.add('subscriber count', len(found.subscriptions[topic]))
    return [report]


def _qos_pairs() -> list[tuple[str, Any, Any, Any, str]]:
    """(topic, publisher, subscription, compatibility, reason) for every pair; the reason as
    rclpy gives it ('ERROR: Best effort publisher...'), which the report shows as is."""
    from rclpy.qos import qos_check_compatible
    found = graph()
    pairs = []
    for topic, _ in found.topics:
        for pub in found.publishers[topic]:
            for sub in found.subscriptions[topic]:
                compatibility, reason = qos_check_compatible(pub.qos_profile, sub.qos_profile)
                pairs.append((topic, pub, sub, compatibility, reason))
    return pairs


def check_qos() -> Result:
    from rclpy.qos import QoSCompatibility
    result = Result()
    if _graph_or_failure(result) is None:
        return result
    for topic, _, _, compatibility, reason in _qos_pairs():
        # The check's line says warning/error itself: without rclpy's leading 'ERROR: '.
        reason = re.sub(r'^(?i:warning|error): ', '', reason)
        if compatibility == QoSCompatibility.WARNING:
            result.warn(f"QoS compatibility warning found on topic '{topic}': {reason}")
        elif compatibility == QoSCompatibility.ERROR:
            result.fail(f"QoS compatibility error found on topic '{topic}': {reason}")
    return result


def report_qos() -> list[Report]:
    from rclpy.qos import QoSCompatibility
    report = Report('QOS COMPATIBILITY LIST')
    for topic, pub, sub, compatibility, reason in _qos_pairs():
        report.add('topic [type]', f'{topic} [{pub.topic_type}]')
        report.add('publisher node', pub.node_name)
        report.add('subscriber node', sub.node_name)
        report.add('compatibility status',
                   'OK' if compatibility == QoSCompatibility.OK else reason)
    if not report.items:
        report.add('compatibility status', 'No publisher/subscriber pairs found')
    return [report]


# --------------------------------------------------------------------------------------
# package versions against requirements.lock
# --------------------------------------------------------------------------------------

def find_lock() -> str | None:
    """requirements.lock beside the install/ space of a sourced workspace (innermost first)."""
    for prefix in os.environ.get('COLCON_PREFIX_PATH', '').split(os.pathsep):
        if prefix:
            candidate = os.path.join(os.path.dirname(os.path.abspath(prefix)),
                                     'requirements.lock')
            if os.path.isfile(candidate):
                return candidate
    return None


def _locked_versions(path: str) -> dict[str, str]:
    pins = {}
    with open(path, encoding='utf-8') as lock:
        for line in lock:
            line = line.split('#', 1)[0].strip()
            if '==' in line:
                name, version = line.split('==', 1)
                pins[name.split('[', 1)[0].strip()] = version.split(';', 1)[0].strip()
    return pins


def _local_version(name: str) -> str | None:
    from importlib.metadata import PackageNotFoundError, version
    try:
        return version(name)
    except PackageNotFoundError:
        return None


def check_packages() -> Result:
    result = Result()
    lock = find_lock()
    if lock is None:
        result.warn('No requirements.lock found beside any workspace in COLCON_PREFIX_PATH: '
                    'package versions not checked.')
        return result
    for name, pinned in sorted(_locked_versions(lock).items()):
        local = _local_version(name)
        if local is None:
            result.warn(f"Package '{name}' is pinned to {pinned} in {lock} but not installed.")
        elif local != pinned:
            result.warn(f"Package '{name}' is {local} here but {lock} pins {pinned}.")
    return result


def report_packages() -> list[Report]:
    report = Report('PACKAGE VERSIONS')
    lock = find_lock()
    if lock is None:
        report.add('requirements.lock', 'not found')
        return [report]
    report.add('requirements.lock', lock)
    for name, pinned in sorted(_locked_versions(lock).items()):
        report.add(name, f'locked={pinned}, local={_local_version(name) or "missing"}')
    return [report]


# (category, check) in the order Jazzy runs its checks; reports likewise.
CHECKS: list[tuple[str, Callable[[], Result]]] = [
    ('platform', check_platform), ('network', check_network),
    ('middleware', check_middleware), ('topic', check_topics),
    ('middleware', check_qos), ('package', check_packages),
]
REPORTS: list[tuple[str, Callable[[], list[Report]]]] = [
    ('platform', report_platform), ('network', report_network),
    ('middleware', report_middleware), ('topic', report_topics),
    ('middleware', report_qos), ('package', report_packages),
]
