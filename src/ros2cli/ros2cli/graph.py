"""The ROS graph as plain data, from the `ros2` daemon or (with use_daemon=False) from DDS directly.

    from ros2cli.graph import get_graph
    graph = get_graph()                       # starts the daemon on first use
    graph.node_names()                        # ['/turtlesim', ...]
    graph.topics(include_hidden=False)        # [('/turtle1/pose', ['turtlesim/msg/Pose']), ...]
    graph.actions()                           # [('/turtle1/rotate_absolute', [...])]
    graph.node('/turtlesim')                  # NodeInfo: publishers, ..., action_clients

Every list is sorted and holds plain strings, so it serialises as JSON unchanged. Participants
on this host whose process has died are left out (see `snapshot`): a SIGKILLed node vanishes at
once instead of when its DDS lease expires.

Nothing here imports rclpy at module level: with the daemon answering, a graph query costs a
Unix socket round trip.
"""

from __future__ import annotations

import os
import time
from collections import Counter
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any, NamedTuple

from ros2cli.verb_context import VerbContext

NamesAndTypes = list[tuple[str, list[str]]]
ENTITY_KINDS = ('subscribers', 'publishers', 'service_servers', 'service_clients',
                'action_servers', 'action_clients')
_ACTION_FEEDBACK = '/_action/feedback'
_FEEDBACK_SUFFIX = '_FeedbackMessage'


def _hidden(name: str) -> bool:
    return any(token.startswith('_') for token in name.split('/'))


def _full_name(name: str, namespace: str) -> str:
    return namespace.rstrip('/') + '/' + name


class NodeInfo(NamedTuple):
    """What one node offers: each kind is [(name, [types])], sorted by name, hidden included."""

    name: str
    namespace: str
    subscribers: NamesAndTypes
    publishers: NamesAndTypes
    service_servers: NamesAndTypes
    service_clients: NamesAndTypes
    action_servers: NamesAndTypes
    action_clients: NamesAndTypes

    @property
    def full_name(self) -> str:
        return _full_name(self.name, self.namespace)


class Graph:
    """One snapshot of the graph (see `snapshot` for the data it wraps)."""

    def __init__(self, data: dict[str, Any]) -> None:
        self.data = data

    def nodes(self, include_hidden: bool = False) -> list[tuple[str, str]]:
        """(name, namespace) of every node, sorted by full name; duplicates kept."""
        found = [(n, ns) for n, ns in self.data['nodes'] if include_hidden or not n.startswith('_')]
        return sorted(found, key=lambda item: _full_name(*item))

    def node_names(self, include_hidden: bool = False) -> list[str]:
        return [_full_name(n, ns) for n, ns in self.nodes(include_hidden)]

    def _named(self, key: str, include_hidden: bool) -> NamesAndTypes:
        return [(entry[0], list(entry[1])) for entry in self.data[key]
                if include_hidden or not _hidden(entry[0])]

    def topics(self, include_hidden: bool = False) -> NamesAndTypes:
        return self._named('topics', include_hidden)

    def services(self, include_hidden: bool = False) -> NamesAndTypes:
        return self._named('services', include_hidden)

    def actions(self) -> NamesAndTypes:
        return self._named('actions', True)

    def topic_counts(self, topic: str) -> tuple[int, int]:
        """(publishers, subscribers) of a topic, (0, 0) when unknown."""
        for name, _, publishers, subscribers in self.data['topics']:
            if name == topic:
                return publishers, subscribers
        return 0, 0

    def service_counts(self, service: str) -> tuple[int, int]:
        """(servers, clients) of a service, (0, 0) when unknown."""
        for name, _, servers, clients in self.data['services']:
            if name == service:
                return servers, clients
        return 0, 0

    def node(self, full_name: str) -> NodeInfo | None:
        """The entities of a node (needs a snapshot taken with detail=True)."""
        details = self.data.get('details', {}).get(full_name)
        if details is None:
            return None
        name, namespace, entities = details
        return NodeInfo(name, namespace, **{kind: [(n, list(t)) for n, t in entities[kind]]
                                            for kind in ENTITY_KINDS})

    def action_endpoints(self, action: str) -> tuple[list[tuple[str, list[str]]], ...]:
        """([(server node, types)], [(client node, types)]) of an action (detail=True)."""
        servers, clients = [], []
        for full in sorted(self.data.get('details', {})):
            info = self.node(full)
            assert info is not None
            servers += [(full, t) for n, t in info.action_servers if n == action]
            clients += [(full, t) for n, t in info.action_clients if n == action]
        return servers, clients


# --------------------------------------------------------------------------------------
# Where the graph comes from: the daemon or a CLI node of our own
# --------------------------------------------------------------------------------------

class GraphSource:
    """Answers graph queries; `ready` predicates are waited for up to `bound` seconds."""

    def graph(self, detail: bool = False, ready: Callable[[Graph], bool] | None = None,
              bound: float | None = None) -> Graph:
        raise NotImplementedError

    def endpoints(self, topic: str) -> tuple[list[str], list[str]]:
        """Printable endpoint infos (as `ros2 topic info -v` shows) of publishers, subscribers."""
        raise NotImplementedError


class _DaemonSource(GraphSource):
    def __init__(self, spin_time: float | None = None) -> None:
        self.spin_time = spin_time

    def graph(self, detail: bool = False, ready: Callable[[Graph], bool] | None = None,
              bound: float | None = None) -> Graph:
        from ros2cli.daemon.client import request
        if bound is None:
            bound = _lookup_bound(self.spin_time)
        deadline = time.monotonic() + bound
        while True:
            graph = Graph(request({'op': 'graph', 'detail': detail})['graph'])
            if ready is None or ready(graph) or time.monotonic() >= deadline:
                return graph
            time.sleep(0.05)

    def endpoints(self, topic: str) -> tuple[list[str], list[str]]:
        from ros2cli.daemon.client import request
        reply = request({'op': 'endpoints', 'topic': topic})
        return reply['publishers'], reply['subscribers']


class _DirectSource(GraphSource):
    """Today's daemon-less discovery: a fresh hidden node that waits for the graph to settle."""

    def __init__(self, node: Any, spin_time: float | None, context: VerbContext) -> None:
        self.node = node
        self.spin_time = spin_time
        self.context = context

    def graph(self, detail: bool = False, ready: Callable[[Graph], bool] | None = None,
              bound: float | None = None) -> Graph:
        from ros2cli.node.discovery import wait_for_graph
        if bound is None:
            bound = self.spin_time
        if ready is None:
            wait_for_graph(self.node, bound=bound, context=self.context)
        else:
            wait_for_graph(self.node, ready=lambda: ready(Graph(snapshot(self.node, detail))),
                           settle=0.2, bound=bound, context=self.context)
        return Graph(snapshot(self.node, detail))

    def endpoints(self, topic: str) -> tuple[list[str], list[str]]:
        return endpoint_texts(self.node, topic)


def _lookup_bound(spin_time: float | None) -> float:
    """How long a daemon-answered lookup waits for a named entity that is not there (yet)."""
    # A node that has just started can take DDS up to ~3 s to announce on a loaded machine
    # (measured): the daemon's cache is complete only for what has been announced.
    return spin_time if spin_time is not None else 4.0


@contextmanager
def graph_source(use_daemon: bool = True, spin_time: float | None = None,
                 context: VerbContext | None = None) -> Iterator[GraphSource]:
    """The daemon (started on first use), or with use_daemon=False a CLI node of our own.

    `spin_time` (a verb's --spin-time) bounds the waits for a named entity to appear; a verb
    passes its `context` (default: this process's, for code outside the CLI).
    """
    if use_daemon:
        yield _DaemonSource(spin_time)
        return
    from ros2cli.node.direct import cli_node
    context = context or VerbContext.here()
    with cli_node(context, spin_time=spin_time) as node:
        yield _DirectSource(node, spin_time, context)


def get_graph(use_daemon: bool = True, detail: bool = True) -> Graph:
    """One complete snapshot of the graph (for code outside the CLI, e.g. a web UI)."""
    with graph_source(use_daemon) as source:
        return source.graph(detail=detail)


# --------------------------------------------------------------------------------------
# Building a snapshot from an rclpy node (in the daemon, or in the CLI with --no-daemon)
# --------------------------------------------------------------------------------------

_FASTDDS_VENDOR = b'\x01\x0f'


class _Liveness:
    """Tells whether the process behind a Fast DDS GUID prefix on this host is gone.

    Fast DDS 2.14 (GuidUtils) builds a participant's GUID prefix as: vendor id (01 0f), host
    id (2 bytes, the same for every process on a host), the 16 low bits of the process id
    (little endian), 2 random bytes, then the participant counter. Checked on this machine:
    two processes of pids 0x4abc and 0x4adf had prefixes 01.0f.78.fd.bc.4a... and
    01.0f.78.fd.df.4a... So for a prefix with our own host id, no live (non-zombie) process
    whose pid ends in those 16 bits means the participant is dead, even while DDS still lists
    it until its lease expires. Prefixes of other hosts or vendors are always kept.
    """

    def __init__(self, own_gid: bytes | None) -> None:
        self._host = own_gid[2:4] if own_gid and own_gid[:2] == _FASTDDS_VENDOR else None
        self._pids: dict[int, list[int]] | None = None
        self._verdicts: dict[int, bool] = {}

    def dead(self, gid: bytes) -> bool:
        if self._host is None or gid[:2] != _FASTDDS_VENDOR or gid[2:4] != self._host:
            return False
        low = gid[4] | gid[5] << 8
        if low not in self._verdicts:
            self._verdicts[low] = not any(_running(pid) for pid in self._candidates(low))
        return self._verdicts[low]

    def _candidates(self, low: int) -> list[int]:
        if self._pids is None:
            self._pids = {}
            for entry in os.listdir('/proc'):
                if entry.isdigit():
                    self._pids.setdefault(int(entry) & 0xFFFF, []).append(int(entry))
        return self._pids.get(low, [])


def _running(pid: int) -> bool:
    """The process exists and is not a zombie (a killed child not reaped yet has no DDS)."""
    try:
        with open(f'/proc/{pid}/stat', 'rb') as stat:
            state = stat.read().rsplit(b')', 1)[1].split()[0]
    except (OSError, IndexError):
        return False
    return state not in (b'Z', b'X')


def _own_gid(node: Any) -> bytes | None:
    name, namespace = node.get_name(), node.get_namespace()
    for info in node.get_publishers_info_by_topic('/rosout'):
        if info.node_name == name and info.node_namespace == namespace:
            return bytes(info.endpoint_gid)
    return None


def _endpoint_infos(node: Any, raw: str) -> tuple[list[Any], list[Any]]:
    return (node.get_publishers_info_by_topic(raw, no_mangle=True),
            node.get_subscriptions_info_by_topic(raw, no_mangle=True))


def snapshot(node: Any, detail: bool = False) -> dict[str, Any]:
    """The graph as `node` sees it now, without the participants of dead local processes.

    DDS-level endpoints (raw names `rt/...` for topics, `rq/...Request` for services) carry the
    GUIDs whose prefixes tell which participant, hence which process, owns them; nodes are tied
    to participants through the node names on their endpoints. A node without any endpoint
    cannot be tied to a participant and is always kept.
    """
    from rclpy.action.graph import (
        get_action_client_names_and_types_by_node,
        get_action_server_names_and_types_by_node,
    )

    liveness = _Liveness(_own_gid(node))
    hosts: dict[tuple[str, str], set[bytes]] = {}   # node -> participant prefixes
    dead_participants: set[bytes] = set()
    live_counts: dict[str, tuple[int, int]] = {}
    for raw, _ in node.get_topic_names_and_types(no_demangle=True):
        if not raw.startswith(('rt/', 'rq/')):
            continue
        # Services: requests are written by clients and read by servers.
        writers, readers = _endpoint_infos(node, raw)
        counts = [0, 0]
        for index, infos in enumerate((writers, readers)):
            for info in infos:
                gid = bytes(info.endpoint_gid)
                hosts.setdefault((info.node_name, info.node_namespace), set()).add(gid[:12])
                if liveness.dead(gid):
                    dead_participants.add(gid[:12])
                else:
                    counts[index] += 1
        live_counts[raw] = (counts[0], counts[1])

    listed = Counter(node.get_node_names_and_namespaces())
    nodes: list[tuple[str, str]] = []
    for key, count in listed.items():
        # A name that k participants hold, d of them dead, is listed k - d times.
        dead = len(hosts.get(key, set()) & dead_participants)
        nodes += [key] * max(0, count - dead)

    topics = []
    for name, types in node.get_topic_names_and_types():
        publishers, subscribers = live_counts.get('rt' + name, (1, 0))
        if publishers + subscribers:
            topics.append((name, sorted(types), publishers, subscribers))
    services = []
    for name, types in node.get_service_names_and_types():
        clients, servers = live_counts.get('rq' + name + 'Request', (0, 1))
        if servers + clients:
            services.append((name, sorted(types), servers, clients))
    actions = sorted(
        (name[:-len(_ACTION_FEEDBACK)],
         sorted(t[:-len(_FEEDBACK_SUFFIX)] for t in types if t.endswith(_FEEDBACK_SUFFIX)))
        for name, types, *_ in topics if name.endswith(_ACTION_FEEDBACK))
    data: dict[str, Any] = {'nodes': sorted(nodes), 'topics': topics, 'services': services,
                            'actions': actions}
    # Each node's security enclave ('/' unless set), for ros2cli.node.daemon's query of them.
    data['enclaves'] = {_full_name(n, ns): enclave for n, ns, enclave
                        in node.get_node_names_and_namespaces_with_enclaves()}
    if detail:
        queries = (
            ('subscribers', node.get_subscriber_names_and_types_by_node),
            ('publishers', node.get_publisher_names_and_types_by_node),
            ('service_servers', node.get_service_names_and_types_by_node),
            ('service_clients', node.get_client_names_and_types_by_node),
            ('action_servers', lambda n, ns: get_action_server_names_and_types_by_node(
                node, n, ns)),
            ('action_clients', lambda n, ns: get_action_client_names_and_types_by_node(
                node, n, ns)),
        )
        details = {}
        for name, namespace in set(nodes):
            entities = {}
            for kind, query in queries:
                try:
                    entities[kind] = sorted((n, list(t)) for n, t in query(name, namespace))
                except Exception:  # the node left between the two calls
                    entities[kind] = []
            details[_full_name(name, namespace)] = (name, namespace, entities)
        data['details'] = details
    return data


def endpoint_records(node: Any, topic: str) -> tuple[list[dict], list[dict]]:
    """The live publishers and subscribers of a topic as plain data: TopicEndpointInfo's
    fields, QoS durations in nanoseconds (ros2cli.node.daemon rebuilds the infos)."""
    liveness = _Liveness(_own_gid(node))

    def record(info: Any) -> dict[str, Any]:
        qos = info.qos_profile
        return {
            'node_name': info.node_name, 'node_namespace': info.node_namespace,
            'topic_type': info.topic_type, 'endpoint_type': int(info.endpoint_type),
            'endpoint_gid': list(info.endpoint_gid),
            'qos': {'history': int(qos.history), 'depth': qos.depth,
                    'reliability': int(qos.reliability), 'durability': int(qos.durability),
                    'liveliness': int(qos.liveliness),
                    **{key: getattr(qos, key).nanoseconds for key in
                       ('deadline', 'lifespan', 'liveliness_lease_duration')}}}
    return tuple(  # type: ignore[return-value]
        [record(info) for info in infos if not liveness.dead(bytes(info.endpoint_gid))]
        for infos in (node.get_publishers_info_by_topic(topic),
                      node.get_subscriptions_info_by_topic(topic)))


def endpoint_texts(node: Any, topic: str) -> tuple[list[str], list[str]]:
    """`str()` of the live publishers' and subscribers' TopicEndpointInfo of a topic."""
    liveness = _Liveness(_own_gid(node))
    return tuple(  # type: ignore[return-value]
        [str(info) for info in infos if not liveness.dead(bytes(info.endpoint_gid))]
        for infos in (node.get_publishers_info_by_topic(topic),
                      node.get_subscriptions_info_by_topic(topic)))
