"""Parameters of every node, through the nodes' own parameter services (as upstream).

A client names a parameter `/node.param` (upstream's form: fully qualified node name, a dot,
the parameter). Values travel as the protocol's JSON values: numbers, booleans, strings,
arrays, with `float64`/`float64_array`/`byte_array` type hints where JSON alone would lose
the type. Updates come from /parameter_events, for the names some client subscribed to.
"""

from __future__ import annotations

import base64
import threading
import time
from collections.abc import Callable, Hashable
from concurrent.futures import ThreadPoolExecutor
from typing import Any

from rcl_interfaces.msg import Parameter, ParameterEvent, ParameterType, ParameterValue
from rclpy.node import Node
from rclpy.parameter_client import AsyncParameterClient

from foxglove_bridge.parameters import allowed

TIMEOUT = 3.0  # seconds per node for a parameter service call
PARAMETER_SERVICES = {'rcl_interfaces/srv/ListParameters', 'rcl_interfaces/srv/GetParameters'}


class ParameterError(Exception):
    pass


def to_json(value: ParameterValue) -> tuple[Any, str | None] | None:
    """(JSON value, type hint) of a ROS parameter value; None when it is not set."""
    kind = value.type
    if kind == ParameterType.PARAMETER_BOOL:
        return value.bool_value, None
    if kind == ParameterType.PARAMETER_INTEGER:
        return value.integer_value, None
    if kind == ParameterType.PARAMETER_DOUBLE:
        return value.double_value, 'float64'
    if kind == ParameterType.PARAMETER_STRING:
        return value.string_value, None
    if kind == ParameterType.PARAMETER_BYTE_ARRAY:
        return base64.b64encode(bytes(value.byte_array_value)).decode(), 'byte_array'
    if kind == ParameterType.PARAMETER_BOOL_ARRAY:
        return list(value.bool_array_value), None
    if kind == ParameterType.PARAMETER_INTEGER_ARRAY:
        return list(value.integer_array_value), None
    if kind == ParameterType.PARAMETER_DOUBLE_ARRAY:
        return list(value.double_array_value), 'float64_array'
    if kind == ParameterType.PARAMETER_STRING_ARRAY:
        return list(value.string_array_value), None
    return None


INT64 = (-2**63, 2**63 - 1)


def _integer(name: str, value: int) -> int:
    if not INT64[0] <= value <= INT64[1]:
        raise ParameterError(f"Parameter '{name}': integer {value} is out of the 64-bit range")
    return value


def _double(name: str, value: float) -> float:
    try:
        return float(value)
    except OverflowError:
        raise ParameterError(f"Parameter '{name}': {value} is too large for a float64") from None


def from_json(name: str, value: Any, hint: str | None) -> ParameterValue:
    """The ROS value for a client's JSON value; ParameterError names what is wrong."""
    out = ParameterValue()
    if hint == 'byte_array' and isinstance(value, str):
        try:
            data = base64.b64decode(value, validate=True)
        except ValueError:
            raise ParameterError(f"Parameter '{name}': byte_array value is not base64") from None
        out.type, out.byte_array_value = ParameterType.PARAMETER_BYTE_ARRAY, [
            bytes([b]) for b in data]
    elif isinstance(value, bool):
        out.type, out.bool_value = ParameterType.PARAMETER_BOOL, value
    elif isinstance(value, int) and hint != 'float64':
        out.type, out.integer_value = ParameterType.PARAMETER_INTEGER, _integer(name, value)
    elif isinstance(value, (int, float)):
        out.type, out.double_value = ParameterType.PARAMETER_DOUBLE, _double(name, value)
    elif isinstance(value, str):
        out.type, out.string_value = ParameterType.PARAMETER_STRING, value
    elif isinstance(value, list) and all(isinstance(v, bool) for v in value) and value:
        out.type, out.bool_array_value = ParameterType.PARAMETER_BOOL_ARRAY, value
    elif isinstance(value, list) and all(isinstance(v, str) for v in value) and value:
        out.type, out.string_array_value = ParameterType.PARAMETER_STRING_ARRAY, value
    elif (isinstance(value, list) and all(isinstance(v, int) and not isinstance(v, bool)
                                          for v in value) and hint != 'float64_array'):
        out.type, out.integer_array_value = ParameterType.PARAMETER_INTEGER_ARRAY, [
            _integer(name, v) for v in value]
    elif isinstance(value, list) and all(isinstance(v, (int, float)) and not isinstance(v, bool)
                                         for v in value):
        out.type, out.double_array_value = ParameterType.PARAMETER_DOUBLE_ARRAY, [
            _double(name, v) for v in value]
    else:
        raise ParameterError(f"Parameter '{name}': unsupported value {value!r} (allowed: bool, "
                             'integer, float, string, byte_array or arrays of one of them)')
    return out


def split_name(full: str) -> tuple[str, str]:
    node, dot, param = full.partition('.')
    if not dot or not node.startswith('/') or not param:
        raise ParameterError(f"Invalid parameter name '{full}': expected '/node_name.param'")
    return node, param


def _wait(future: Any, what: str, timeout: float = TIMEOUT) -> Any:
    done = threading.Event()
    future.add_done_callback(lambda _f: done.set())
    if not done.wait(max(0.0, timeout)):
        raise ParameterError(f'{what}: no answer within {TIMEOUT} s')
    if future.exception() is not None:
        raise ParameterError(f'{what}: {future.exception()}')
    return future.result()


class ParameterAccess:
    def __init__(self, node: Node, whitelist: list[Any],
                 on_change: Callable[[list[dict[str, Any]]], None]) -> None:
        self._node = node
        self._whitelist = whitelist
        self._on_change = on_change
        self._clients: dict[str, AsyncParameterClient] = {}
        self._lock = threading.Lock()
        self._watched: dict[str, set[Hashable]] = {}
        # Nodes that failed a request for all parameters: not asked again (upstream's
        # ignore_unresponsive_param_nodes, on by default there).
        self._ignored: set[str] = set()
        # One thread per node asked at once, as upstream's std::async per node.
        self._pool = ThreadPoolExecutor(max_workers=8, thread_name_prefix='parameters')
        node.create_subscription(ParameterEvent, '/parameter_events', self._on_event, 100)

    def _client(self, node_name: str) -> AsyncParameterClient:
        with self._lock:
            client = self._clients.get(node_name)
            if client is None:
                client = self._node.on_ros_thread(AsyncParameterClient, self._node, node_name)
                self._clients[node_name] = client
            return client

    @staticmethod
    def entry(name: str, value: ParameterValue) -> dict[str, Any] | None:
        converted = to_json(value)
        if converted is None:
            return None
        entry = {'name': name, 'value': converted[0]}
        if converted[1]:
            entry['type'] = converted[1]
        return entry

    def _nodes(self) -> list[str]:
        own = self._node.get_fully_qualified_name()
        names = []
        for name, namespace in self._node.get_node_names_and_namespaces():
            full = f"{namespace.rstrip('/')}/{name}"
            if full != own:
                names.append(full)
        return names

    def _offers_parameters(self, full: str) -> bool:
        """Whether the node has list_parameters and get_parameters services (rclpy and rclcpp
        nodes do; the ros2 daemon's and the rqt web app's node do not, and would never answer).
        """
        namespace, _slash, name = full.rpartition('/')
        try:
            services = self._node.get_service_names_and_types_by_node(name, namespace or '/')
        except Exception:  # the node left the graph meanwhile (NodeNameNonExistentError)
            return False
        types = {t for _service, kinds in services for t in kinds}
        return PARAMETER_SERVICES <= types

    def _node_values(self, node: str, params: list[str] | None) -> list[tuple[str, Any]]:
        """(name, value) of `params` on `node`, or of all its whitelisted ones when None."""
        deadline = time.monotonic() + TIMEOUT
        client = self._client(node)
        while not client.services_are_ready():
            if time.monotonic() > deadline:
                raise ParameterError(f"Parameter service for node '{node}' is not ready")
            time.sleep(0.01)
        if params is None:
            try:
                listed = _wait(client.list_parameters(), f'{node} list',
                               deadline - time.monotonic())
            except ParameterError:
                raise ParameterError(
                    f"Failed to retrieve parameter names for node '{node}'") from None
            params = [p for p in listed.result.names
                      if allowed(self._whitelist, f'{node}.{p}')]
        if not params:
            return []
        try:
            values = _wait(client.get_parameters(params), f'{node} get',
                           deadline - time.monotonic())
        except ParameterError:
            raise ParameterError(f'Timed out waiting for {len(params)} parameter(s) from '
                                 f"node '{node}'") from None
        return list(zip(params, values.values, strict=False))

    def get(self, names: list[str]) -> list[dict[str, Any]]:
        """Values of `names`, or of every whitelisted parameter when `names` is empty.

        Nodes are asked in parallel. For all parameters, only nodes that offer the parameter
        services are asked, and a node that fails is logged once and never asked again (as
        upstream); a failure for parameters asked by name is the client's error.
        """
        wanted: dict[str, list[str] | None] = {}
        if names:
            present = set(self._nodes())
            for full in names:
                node, param = split_name(full)
                if node in present and allowed(self._whitelist, full):
                    # no client (and no 3 s wait) for a node that is not there
                    wanted.setdefault(node, []).append(param)
        else:
            for node in self._nodes():
                if node not in self._ignored and self._offers_parameters(node):
                    wanted[node] = None
        futures = {node: self._pool.submit(self._node_values, node, params)
                   for node, params in wanted.items()}
        result, failure = [], None
        for node, future in futures.items():
            try:
                values = future.result()
            except ParameterError as error:
                if names:
                    failure = failure or error
                else:
                    self._ignore(node, error)
                continue
            for param, value in values:
                entry = self.entry(f'{node}.{param}', value)
                if entry:
                    result.append(entry)
        if failure is not None:
            raise failure
        return result

    def _ignore(self, node: str, error: ParameterError) -> None:
        with self._lock:
            if node in self._ignored:
                return
            self._ignored.add(node)
        logger = self._node.get_logger()
        logger.error(f"Failed to retrieve parameters from node '{node}': {error}")
        logger.warn(f'Adding node {node} to the ignore list to prevent repeated timeouts or '
                    'failures in future parameter requests.')

    def set(self, items: list[tuple[str, Any, str | None]]) -> list[dict[str, Any]]:
        """Set (name, value, hint) items; returns the values the nodes now hold."""
        by_node: dict[str, list[Parameter]] = {}
        present = set(self._nodes())
        for full, value, hint in items:
            node, param = split_name(full)
            if not allowed(self._whitelist, full):
                raise ParameterError(f"Parameter '{full}' is not whitelisted (param_whitelist)")
            if node not in present:
                raise ParameterError(f"Parameter '{full}': node '{node}' not found")
            by_node.setdefault(node, []).append(Parameter(name=param,
                                                          value=from_json(full, value, hint)))
        failures = []
        for node, params in by_node.items():
            client = self._client(node)
            future = client.set_parameters([_to_rclpy(p) for p in params])
            results = _wait(future, f'{node} set')
            for param, result in zip(params, results.results, strict=False):
                if not result.successful:
                    failures.append(f"'{node}.{param.name}': {result.reason}")
        if failures:
            raise ParameterError('Failed to set ' + '; '.join(failures))
        return self.get([full for full, _value, _hint in items])

    def watch(self, watcher: Hashable, names: list[str], on: bool) -> None:
        with self._lock:
            for name in names:
                holders = self._watched.setdefault(name, set())
                (holders.add if on else holders.discard)(watcher)
                if not holders:
                    del self._watched[name]

    def forget(self, watcher: Hashable) -> None:
        with self._lock:
            for name in list(self._watched):
                self._watched[name].discard(watcher)
                if not self._watched[name]:
                    del self._watched[name]

    def _on_event(self, event: ParameterEvent) -> None:
        if not self._watched:
            return
        updates = []
        for param in [*event.new_parameters, *event.changed_parameters]:
            full = f'{event.node}.{param.name}'
            if full in self._watched:
                entry = self.entry(full, param.value)
                if entry:
                    updates.append(entry)
        if updates:
            self._on_change(updates)


def _to_rclpy(param: Parameter) -> Any:
    from rclpy.parameter import Parameter as RclpyParameter
    return RclpyParameter.from_parameter_msg(param)
