"""DaemonNode and the daemon's life cycle, as upstream's ros2cli.node.daemon names them.

The daemon is ros2cli.daemon's (`ros2 daemon start/stop/status`): one per shell's ROS settings,
reached through a Unix socket. DaemonNode answers the graph queries from the daemon's settled
view of the graph, in rclpy's shapes (lists of [name, namespace], [name, [types]]).
"""

from __future__ import annotations

import argparse
import time
from typing import Any

from ros2cli.daemon import client

# The graph queries a DaemonNode answers; NodeStrategy asks its direct node for the rest.
# (DaemonNode method, NodeInfo field) of the per-node queries.
BY_NODE = (('get_subscriber_names_and_types_by_node', 'subscribers'),
           ('get_publisher_names_and_types_by_node', 'publishers'),
           ('get_service_names_and_types_by_node', 'service_servers'),
           ('get_client_names_and_types_by_node', 'service_clients'),
           ('get_action_server_names_and_types_by_node', 'action_servers'),
           ('get_action_client_names_and_types_by_node', 'action_clients'))
METHODS = ('get_name', 'get_namespace', 'get_node_names_and_namespaces',
           'get_node_names_and_namespaces_with_enclaves', 'get_topic_names_and_types',
           'get_service_names_and_types', 'get_action_names_and_types',
           'get_publishers_info_by_topic', 'get_subscriptions_info_by_topic',
           'count_publishers', 'count_subscribers', 'count_services', 'count_clients',
           *(method for method, _ in BY_NODE))


class _System:
    """`node.system.shutdown()`: upstream's XML-RPC call that stops the daemon."""

    def shutdown(self) -> bool:
        return client.stop()


class DaemonNode:
    """The running daemon, as a node answering graph queries (see METHODS)."""

    def __init__(self, args: Any) -> None:
        self._args = args
        self._methods: list[str] = []
        self.system = _System()

    @property
    def connected(self) -> bool:
        """Whether a daemon answers (and what it can be asked then, in `methods`)."""
        running = client.is_running()
        self._methods = list(METHODS) if running else []
        return running

    @property
    def methods(self) -> list[str]:
        return self._methods

    def __enter__(self) -> DaemonNode:
        return self

    def __exit__(self, exc_type: Any, exc_value: Any, traceback: Any) -> None:
        pass

    def _graph(self, detail: bool = False) -> Any:
        from ros2cli.graph import Graph
        return Graph(client.request({'op': 'graph', 'detail': detail})['graph'])

    def __getattr__(self, name: str) -> Any:
        # The per-node queries (BY_NODE): [name, [types]] of one entity kind of a node.
        kind = dict(BY_NODE).get(name)
        if kind is None:
            raise AttributeError(f"'DaemonNode' object has no attribute '{name}'")

        def by_node(node_name: str, node_namespace: str) -> list[list[Any]]:
            full = node_namespace.rstrip('/') + '/' + node_name
            info = self._graph(detail=True).node(full)
            return [] if info is None else [[n, t] for n, t in getattr(info, kind)]
        return by_node

    def _endpoints(self, topic: str, index: int) -> list[Any]:
        from rclpy.duration import Duration
        from rclpy.topic_endpoint_info import TopicEndpointInfo
        reply = client.request({'op': 'endpoint_records', 'topic': topic})
        infos = []
        for record in reply[('publishers', 'subscribers')[index]]:
            qos = dict(record.pop('qos'))
            for key in ('deadline', 'lifespan', 'liveliness_lease_duration'):
                qos[key] = Duration(nanoseconds=qos[key])
            infos.append(TopicEndpointInfo(**record, qos_profile=qos))
        return infos

    def get_publishers_info_by_topic(self, topic_name: str) -> list[Any]:
        return self._endpoints(topic_name, 0)

    def get_subscriptions_info_by_topic(self, topic_name: str) -> list[Any]:
        return self._endpoints(topic_name, 1)

    def count_publishers(self, topic_name: str) -> int:
        return self._graph().topic_counts(topic_name)[0]

    def count_subscribers(self, topic_name: str) -> int:
        return self._graph().topic_counts(topic_name)[1]

    def count_services(self, service_name: str) -> int:
        return self._graph().service_counts(service_name)[0]

    def count_clients(self, service_name: str) -> int:
        return self._graph().service_counts(service_name)[1]

    def get_name(self) -> str:
        daemon = [n for n, _ in self._graph().nodes(include_hidden=True)
                  if n.startswith('_ros2cli_daemon')]
        return daemon[0] if daemon else '_ros2cli_daemon'

    def get_namespace(self) -> str:
        return '/'

    def get_node_names_and_namespaces(self) -> list[list[str]]:
        return [[n, ns] for n, ns in self._graph().nodes(include_hidden=True)]

    def get_node_names_and_namespaces_with_enclaves(self) -> list[list[str]]:
        graph = self._graph()
        enclaves = graph.data.get('enclaves', {})
        return [[n, ns, enclaves.get(ns.rstrip('/') + '/' + n, '/')]
                for n, ns in graph.nodes(include_hidden=True)]

    def get_topic_names_and_types(self) -> list[list[Any]]:
        return [[name, types] for name, types in self._graph().topics(include_hidden=True)]

    def get_service_names_and_types(self) -> list[list[Any]]:
        return [[name, types] for name, types in self._graph().services(include_hidden=True)]

    def get_action_names_and_types(self) -> list[list[Any]]:
        return [[name, types] for name, types in self._graph().actions()]


def is_daemon_running(args: Any) -> bool:
    """Whether the daemon of these ROS settings answers."""
    return client.is_running()


def shutdown_daemon(args: Any, timeout: float | None = None) -> bool:
    """Stop the daemon; True when one was running. RuntimeError when it outlives `timeout`."""
    if not client.is_running():
        return False
    client.stop(timeout=timeout if timeout is not None and timeout > 0 else 10.0)
    if timeout is not None and timeout > 0:
        deadline = time.monotonic() + timeout
        while client.is_running():
            if time.monotonic() >= deadline:
                raise RuntimeError('Timed out waiting for daemon to shutdown')
            time.sleep(0.05)
    return True


def spawn_daemon(args: Any, timeout: float | None = None, debug: bool = False) -> bool:
    """Start the daemon unless it runs; True when this call started it (it then answers)."""
    return client.start()


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Upstream's daemon node takes no options of its own."""
