"""Helpers shared by every command: the CLI node, graph discovery, interface types, YAML.

Heavy modules (rclpy, yaml, the generated interfaces) are imported inside the functions that
need them, so `ros2 interface show` or `ros2 run` never pay for DDS.
"""

from __future__ import annotations

import importlib
import os
import sys
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

NODE_NAME_PREFIX = '_ros2cli'
# `--spin-time S` (ros2cli's discovery time without a daemon) overrides the discovery bound.
SPIN_TIME: float | None = None


class CliError(Exception):
    """A verb failed: the message goes to stderr and `ros2` exits with 1."""


def is_hidden(name: str) -> bool:
    """A topic/service name is hidden when any of its `/` tokens starts with `_`."""
    return any(token.startswith('_') for token in name.split('/'))


def is_hidden_node(name: str) -> bool:
    return name.startswith('_')


def print_names(names: list[str], count_only: bool) -> None:
    """One name a line, or with `count_only` (the `-c` of list/find verbs) just how many."""
    if count_only:
        print(len(names))
    else:
        for name in names:
            print(name)


def full_node_name(name: str, namespace: str) -> str:
    return namespace.rstrip('/') + '/' + name


# --------------------------------------------------------------------------------------
# The CLI node and graph discovery
# --------------------------------------------------------------------------------------

def add_graph_verb(verbs: Any, name: str, func: Callable, help_text: str,
                   hidden_flag: str | None = None, hidden_dest: str | None = None) -> Any:
    """A verb parser with the options every graph verb shares (as ros2cli's verbs do)."""
    import argparse

    parser = verbs.add_parser(name, help=help_text, description=help_text)
    if hidden_flag:  # also accepted after the verb, as ros2cli does
        parser.add_argument(hidden_flag, action='store_true', dest=hidden_dest,
                            help=argparse.SUPPRESS)
    parser.add_argument('--spin-time', type=float, default=None,
                        help='Longest wait in seconds for a named entity to appear (default: '
                        '1 with the daemon; with --no-daemon the discovery time: 2 to list, 4 '
                        'to find)')
    parser.add_argument('-s', '--use-sim-time', action='store_true', help=argparse.SUPPRESS)
    parser.add_argument('--no-daemon', action='store_true',
                        help='Do not spawn nor use an already running daemon')
    parser.set_defaults(_main=func)
    return parser


@contextmanager
def cli_node(name: str | None = None, discover: bool = True) -> Iterator[Any]:
    """A hidden node `_ros2cli_<pid>` in a fresh context, torn down on exit.

    With `discover`, make sure the node has met the rest of the graph first (see _meet_graph).
    """
    import rclpy

    node_name = name or f'{NODE_NAME_PREFIX}_{os.getpid()}'
    context, node = _make_node(node_name)
    try:
        if discover:
            context, node = _meet_graph(context, node, node_name)
        yield node
    finally:
        # Shut the executor of spin_once down while its context lives: left to the garbage
        # collector, it would destroy its guard condition after the context and print
        # "Exception ignored in: Executor.__del__ ... InvalidHandle" on stderr.
        executor = getattr(node, '_cli_executor', None)
        if executor is not None:
            executor.shutdown(timeout_sec=1.0)
        node.destroy_node()
        rclpy.try_shutdown(context=context)


def _make_node(name: str) -> tuple[Any, Any]:
    import rclpy
    from rclpy.context import Context
    from rclpy.parameter import Parameter

    context = Context()
    rclpy.init(args=[], context=context)
    # No parameter or type-description services: the CLI node offers nothing to the graph.
    node = rclpy.create_node(
        name, context=context, start_parameter_services=False,
        parameter_overrides=[Parameter('start_type_description_service', value=False)])
    return context, node


def _meet_graph(context: Any, node: Any, name: str, patience: float = 0.4,
                bound: float = 1.8) -> tuple[Any, Any]:
    """Wait until another participant is known; replace ours when it is not met quickly.

    With Fast DDS and localhost-only discovery, a new participant is sometimes not answered
    by the others until their next periodic announcement (up to 3 s later). Normally it meets
    them within ~0.1 s, so after `patience` seconds without anybody a fresh participant is
    tried (the old one is shut down once the new one exists, so both get distinct ports).
    Gives up after `bound` seconds: the graph may well be empty.
    """
    import rclpy

    if SPIN_TIME is not None:
        bound = min(bound, SPIN_TIME)
    start = time.monotonic()
    attempt_start = start
    while True:
        if len(node.get_node_names_and_namespaces()) > 1:
            return context, node
        now = time.monotonic()
        if now - start >= bound:
            return context, node
        if now - attempt_start >= patience and bound - (now - start) > patience:
            node.destroy_node()
            new_context, new_node = _make_node(name)
            rclpy.try_shutdown(context=context)
            context, node = new_context, new_node
            attempt_start = time.monotonic()
        time.sleep(0.01)


def spin_once(node: Any, timeout: float) -> None:
    """Process pending callbacks of `node` for at most `timeout` seconds."""
    executor = getattr(node, '_cli_executor', None)
    if executor is None:
        executor = _cli_executor_class()(context=node.context)
        executor.add_node(node)
        node._cli_executor = executor
    executor.spin_once(timeout_sec=timeout)


def _cli_executor_class() -> type:
    from rclpy.executors import SingleThreadedExecutor

    class CliExecutor(SingleThreadedExecutor):
        """rclpy's executor, quiet when a Ctrl-C cut its __init__ short.

        rclpy's __del__ then reads an attribute __init__ never set and prints "Exception
        ignored ... no attribute '_sigint_gc'" (found by tests/test_clean_exits.py).
        """

        def __del__(self) -> None:
            if hasattr(self, '_sigint_gc'):
                super().__del__()

    return CliExecutor


def graph_snapshot(node: Any) -> tuple:
    return (
        tuple(sorted(node.get_node_names_and_namespaces())),
        tuple((n, tuple(t)) for n, t in node.get_topic_names_and_types()),
        tuple((n, tuple(t)) for n, t in node.get_service_names_and_types()),
    )


def wait_for_graph(node: Any, ready: Callable[[], bool] | None = None, settle: float = 0.4,
                   bound: float | None = None) -> bool:
    """Let discovery run until the graph has stopped changing for `settle` seconds.

    Without a daemon a fresh node knows nothing: poll the graph (cheap, local caches) and return
    once it is stable and complete and, if given, `ready()` holds; never later than `bound`
    seconds. Complete means another node is known and every node's endpoints have arrived (a
    node's name and its endpoints are discovered separately, sometimes far apart under load).
    The default bound is 2 s for listings, 4 s while looking for something that may just
    not be discovered yet (a loaded machine can take that long). Returns whether `ready()` held.
    """
    if bound is None:
        bound = SPIN_TIME if SPIN_TIME is not None else 2.0 if ready is None else 4.0
    start = time.monotonic()
    own = node.get_fully_qualified_name()
    last = None
    changed = start
    while True:
        now = time.monotonic()
        snapshot = graph_snapshot(node)
        others = [(n, ns) for n, ns in snapshot[0] if full_node_name(n, ns) != own]
        complete = bool(others) and all(_has_endpoints(node, n, ns) for n, ns in others)
        snapshot = (*snapshot, complete)
        if snapshot != last:
            last, changed = snapshot, now
        ok = ready() if ready is not None else True
        if ok and complete and now - changed >= settle:
            return True
        if now - start >= bound:
            return ok
        time.sleep(0.02)


def _has_endpoints(node: Any, name: str, namespace: str) -> bool:
    """Whether a node's publishers or services are known; False once it has left the graph."""
    from rclpy._rclpy_pybind11 import NodeNameNonExistentError
    try:
        return bool(node.get_publisher_names_and_types_by_node(name, namespace)
                    or node.get_service_names_and_types_by_node(name, namespace))
    except NodeNameNonExistentError:  # it left between listing the names and asking for this
        return False
def wait_until(predicate: Callable[[], bool], timeout: float, step: float = 0.02) -> bool:
    deadline = time.monotonic() + timeout
    while not predicate():
        if time.monotonic() >= deadline:
            return False
        time.sleep(step)
    return True


# --------------------------------------------------------------------------------------
# Interface types
# --------------------------------------------------------------------------------------

def import_type(name: str, kind: str) -> Any:
    """The generated class for 'pkg/kind/Name' or 'pkg/Name' (kind = msg, srv or action)."""
    parts = name.split('/')
    if len(parts) == 2:
        parts = [parts[0], kind, parts[1]]
    if len(parts) != 3 or not all(parts) or parts[1] != kind:
        raise ValueError(name)
    try:
        module = importlib.import_module(f'{parts[0]}.{parts[1]}')
        return getattr(module, parts[2])
    except (ImportError, AttributeError, ValueError):
        raise ValueError(name) from None


def type_name(msg_class: Any) -> str:
    """'pkg/msg/Name' of a generated class (services: 'pkg/srv/Name_Request')."""
    module = msg_class.__module__.split('.')
    return f'{module[0]}/{module[1]}/{msg_class.__name__}'


# --------------------------------------------------------------------------------------
# Message -> plain data / YAML
# --------------------------------------------------------------------------------------

def message_to_ordered(msg: Any) -> dict:
    return {field: _plain(getattr(msg, field)) for field in msg.get_fields_and_field_types()}


def _plain(value: Any) -> Any:
    if isinstance(value, (bool, int, float, str)):
        return value
    if isinstance(value, bytes):
        return ''.join(chr(c) for c in value)
    if isinstance(value, (list, tuple)) or type(value).__name__ in ('array', 'ndarray'):
        return [_plain(v) for v in value]
    if hasattr(value, 'get_fields_and_field_types'):
        return message_to_ordered(value)
    if hasattr(value, 'item'):  # numpy scalar
        return value.item()
    return value


def _dumper() -> Any:
    import yaml

    class OrderedDumper(yaml.SafeDumper):
        pass

    def represent_dict(dumper: Any, data: dict) -> Any:
        # A node without a flow style: mappings stay in block style even with flow_style
        # (only sequences flow), as rosidl_runtime_py's message_to_yaml prints them.
        return yaml.MappingNode('tag:yaml.org,2002:map', [
            (dumper.represent_data(key), dumper.represent_data(value))
            for key, value in data.items()])

    OrderedDumper.add_representer(dict, represent_dict)
    return OrderedDumper


def to_yaml(data: Any, flow_style: bool = False) -> str:
    """PyYAML block style in field order, as rosidl_runtime_py's message_to_yaml."""
    import yaml
    return yaml.dump(data, Dumper=_dumper(), allow_unicode=True, width=sys.maxsize,
                     default_flow_style=flow_style)


def message_to_yaml(msg: Any, flow_style: bool = False) -> str:
    return to_yaml(message_to_ordered(msg), flow_style)


# --------------------------------------------------------------------------------------
# YAML -> message, with validation
# --------------------------------------------------------------------------------------

def load_values(text: str) -> Any:
    """Parse YAML where mapping keys are always strings: `{off: 1}` is the field `off`.

    PyYAML follows YAML 1.1, where an unquoted `off`/`on`/`yes`/`no` is a boolean; as a key
    that would never match a field name. Values keep the usual resolution.
    """
    import yaml

    class KeysAsStrings(yaml.SafeLoader):
        def construct_mapping(self, node: Any, deep: bool = False) -> dict:
            if isinstance(node, yaml.MappingNode):
                self.flatten_mapping(node)
            mapping = {}
            for key_node, value_node in node.value:
                if isinstance(key_node, yaml.ScalarNode):
                    key = key_node.value
                else:
                    key = self.construct_object(key_node, deep=deep)
                mapping[key] = self.construct_object(value_node, deep=deep)
            return mapping

    KeysAsStrings.add_constructor('tag:yaml.org,2002:map', KeysAsStrings.construct_yaml_map)
    try:
        return yaml.load(text, Loader=KeysAsStrings)
    except yaml.YAMLError as error:
        raise CliError(f'The passed value is not valid YAML: {yaml_problem(error)}') from None


def yaml_problem(error: Any) -> str:
    """A PyYAML error on one line: what is wrong and where (PyYAML spreads it over five)."""
    problem = getattr(error, 'problem', None)
    mark = getattr(error, 'problem_mark', None)
    if not problem:
        return ' '.join(str(error).split())
    if mark is None:
        return problem
    return f'{problem} (line {mark.line + 1}, column {mark.column + 1})'


INTEGER_RANGES = {
    'int8': (-(2**7), 2**7 - 1), 'uint8': (0, 2**8 - 1), 'octet': (0, 2**8 - 1),
    'int16': (-(2**15), 2**15 - 1), 'uint16': (0, 2**16 - 1),
    'int32': (-(2**31), 2**31 - 1), 'uint32': (0, 2**32 - 1),
    'int64': (-(2**63), 2**63 - 1), 'uint64': (0, 2**64 - 1),
}
FLOAT32_MAX = 3.4028234663852886e38
FLOAT_TYPES = ('float', 'double', 'float32', 'float64', 'long double')


class FieldError(ValueError):
    pass


def fill_message(msg: Any, values: Any, prefix: str = '',
                 stamps: list[Callable[[Any], None]] | None = None) -> None:
    """Set the fields of `msg` from a mapping, refusing anything the field cannot hold.

    With `stamps` (a list), a std_msgs/Header given as 'auto' and a builtin_interfaces/Time
    given as 'now' are accepted (as `ros2 topic pub` does): a setter that stamps the field
    with a given Time message is appended for each, to call before every publication.
    """
    if not isinstance(values, dict):
        raise FieldError(f"'{prefix or type_name(type(msg))}' expects a mapping of field names "
                         f'to values, got {_show(values)}')
    fields = list(msg.get_fields_and_field_types())
    slot_types = dict(zip(fields, msg.SLOT_TYPES, strict=True))
    for key, value in values.items():
        path = f'{prefix}{key}'
        if key not in slot_types:
            allowed = ', '.join(fields) if fields else 'none'
            raise FieldError(f"'{path}' is not a field of {type_name(type(msg))} "
                             f'(fields: {allowed})')
        current = getattr(msg, key)
        setattr(msg, key, _convert(slot_types[key], value, current, path, stamps))


def _show(value: Any) -> str:
    if value is None:
        return 'nothing (null)'
    return repr(value)


def _convert(slot_type: Any, value: Any, current: Any, path: str,
             stamps: list[Callable[[Any], None]] | None = None) -> Any:
    from rosidl_parser import definition as d

    if isinstance(slot_type, d.AbstractNestedType):
        if not isinstance(value, list):
            raise FieldError(f"'{path}' must be a list, got {_show(value)}")
        if isinstance(slot_type, d.Array) and len(value) != slot_type.size:
            raise FieldError(f"'{path}' must have exactly {slot_type.size} elements, "
                             f'got {len(value)}')
        if isinstance(slot_type, d.BoundedSequence) and len(value) > slot_type.maximum_size:
            raise FieldError(f"'{path}' can hold at most {slot_type.maximum_size} elements, "
                             f'got {len(value)}')
        element = slot_type.value_type
        if isinstance(element, d.NamespacedType):
            cls = _namespaced_class(element)
            return [_convert(element, v, cls(), f'{path}[{i}]', stamps)
                    for i, v in enumerate(value)]
        return [_convert(element, v, None, f'{path}[{i}]') for i, v in enumerate(value)]
    if isinstance(slot_type, d.NamespacedType):
        target = current if current is not None else _namespaced_class(slot_type)()
        stamp_setter = _stamp_setter(slot_type, value, target) if stamps is not None else None
        if stamp_setter is not None:
            stamps.append(stamp_setter)
            return target
        fill_message(target, value, prefix=f'{path}.', stamps=stamps)
        return target
    if isinstance(slot_type, (d.AbstractString, d.AbstractWString)):
        if not isinstance(value, str):
            raise FieldError(f"'{path}' must be a string, got {_show(value)} "
                             "(quote it, e.g. '\"123\"')")
        limit = getattr(slot_type, 'maximum_size', None)
        if isinstance(limit, int) and len(value) > limit:
            raise FieldError(f"'{path}' can hold at most {limit} characters, got {len(value)}")
        return value
    name = getattr(slot_type, 'typename', None)
    if name == 'boolean':
        if not isinstance(value, bool):
            raise FieldError(f"'{path}' must be a boolean (true or false), got {_show(value)}")
        return value
    if name in INTEGER_RANGES:
        low, high = INTEGER_RANGES[name]
        if isinstance(value, bool) or not isinstance(value, int) or not low <= value <= high:
            raise FieldError(f"'{path}' must be an integer in [{low}, {high}], got {_show(value)}")
        return value if name != 'octet' else bytes([value])
    if name in FLOAT_TYPES:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise FieldError(f"'{path}' must be a number, got {_show(value)}")
        number = float(value)
        if name in ('float', 'float32') and abs(number) > FLOAT32_MAX \
                and abs(number) != float('inf'):
            raise FieldError(f"'{path}' must be a float32 in [-{FLOAT32_MAX:g}, "
                             f'{FLOAT32_MAX:g}], got {_show(value)}')
        return number
    if name in ('char', 'wchar'):
        if isinstance(value, str) and len(value) == 1:
            return value
        raise FieldError(f"'{path}' must be a single character, got {_show(value)}")
    return value


def _stamp_setter(slot_type: Any, value: Any, target: Any) -> Callable[[Any], None] | None:
    """For Header 'auto' / Time 'now', a setter stamping `target` with a Time message."""
    name = '/'.join((*slot_type.namespaces, slot_type.name))
    if name == 'std_msgs/msg/Header' and value == 'auto':
        def stamp_header(now: Any) -> None:
            target.stamp = now
        return stamp_header
    if name == 'builtin_interfaces/msg/Time' and value == 'now':
        def stamp_time(now: Any) -> None:
            target.sec, target.nanosec = now.sec, now.nanosec
        return stamp_time
    return None


def _namespaced_class(slot_type: Any) -> Any:
    module = importlib.import_module('.'.join(slot_type.namespaces))
    return getattr(module, slot_type.name)


def populate(msg: Any, text: str, stamps: list[Callable[[Any], None]] | None = None) -> Any:
    """Fill `msg` from a YAML mapping; CliError('Failed to populate field: ...') on bad input.

    `stamps`: see fill_message.
    """
    values = load_values(text)
    if values is None or values == '':
        values = {}
    if not isinstance(values, dict):
        raise CliError('The passed value needs to be a dictionary in YAML format')
    try:
        fill_message(msg, values, stamps=stamps)
    except FieldError as error:
        raise CliError(f'Failed to populate field: {error}') from None
    return msg
