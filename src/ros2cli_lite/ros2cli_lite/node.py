"""The CLI's own node (ros2cli's direct node): made, met with the graph, spun, torn down.

A verb that talks to the graph itself (echo, pub, call, param get, ...) opens one with
`cli_node()`; how long discovery may take is passed in (`spin_time`, `bound`), never global.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

from ros2cli_lite.api import full_node_name

NODE_NAME_PREFIX = '_ros2cli'


@contextmanager
def cli_node(name: str | None = None, discover: bool = True,
             spin_time: float | None = None) -> Iterator[Any]:
    """A hidden node `_ros2cli_<pid>` in a fresh context, torn down on exit.

    With `discover`, make sure the node has met the rest of the graph first (see _meet_graph),
    for at most `spin_time` seconds when given (a verb's --spin-time).
    """
    import rclpy

    from ros2cli_lite.daemon.proxy import session
    running_for = session()
    node_name = name or f'{NODE_NAME_PREFIX}_{running_for.pid if running_for else os.getpid()}'
    if running_for is not None:
        # In the daemon, for a CLI: a node of the daemon's participant, which knows the graph.
        context = running_for.context
        node = _create_node(node_name, context)
    else:
        context, node = make_node(node_name)
    try:
        if discover and running_for is None:
            bound = 1.8 if spin_time is None else min(1.8, spin_time)
            context, node, _ = _meet_graph(context, node, lambda: make_node(node_name),
                                           bound=bound)
        yield node
    finally:
        # Shut the executor of spin_once down while its context lives: left to the garbage
        # collector, it would destroy its guard condition after the context and print
        # "Exception ignored in: Executor.__del__ ... InvalidHandle" on stderr.
        executor = getattr(node, '_cli_executor', None)
        if executor is not None:
            executor.shutdown(timeout_sec=1.0)
        node.destroy_node()
        if running_for is None:
            rclpy.try_shutdown(context=context)


def meet_graph(name: str, bound: float) -> tuple[Any, Any, bool]:
    """(a fresh context, a node in it, whether it met every participant on this host within
    `bound` seconds): the daemon's, which must not answer before it has."""
    context, node = make_node(name)
    # Never replaced: the others answer a newcomer at their next periodic announcement (every
    # 0.5 s for our nodes), so a fresh participant would only start that wait anew.
    return _meet_graph(context, node, lambda: make_node(name), patience=bound, bound=bound)


def meet_graph_made(make: Callable[[], tuple[Any, Any]], bound: float = 1.8
                    ) -> tuple[Any, Any, bool]:
    """(a context, its node, whether it met every participant on this host within `bound`
    seconds): `make()` gives a fresh context and node, called again for a fresh participant
    when the first is not met quickly (as cli_node's). For a node of another package that
    must see what is already there before it decides (the recorder's)."""
    context, node = make()
    return _meet_graph(context, node, make, bound=bound)


def make_node(name: str) -> tuple[Any, Any]:
    """(a fresh context, a node in it offering no services): the CLI's and the daemon's."""
    import rclpy
    from rclpy.context import Context

    context = Context()
    rclpy.init(args=[], context=context)
    return context, _create_node(name, context)


def _create_node(name: str, context: Any) -> Any:
    import rclpy
    from rclpy.parameter import Parameter

    # No parameter or type-description services: the CLI node offers nothing to the graph.
    return rclpy.create_node(
        name, context=context, start_parameter_services=False,
        parameter_overrides=[Parameter('start_type_description_service', value=False)])


def _meet_graph(context: Any, node: Any, make: Callable[[], tuple[Any, Any]],
                patience: float = 0.7, bound: float = 1.8) -> tuple[Any, Any, bool]:
    """Wait until every participant on this host is known (see participants.py); replace
    ours when they are not met quickly. Returns (context, node, whether everyone was met).

    With Fast DDS and localhost-only discovery, a new participant is sometimes not answered
    by the others until their next periodic announcement (up to 3 s later; 0.5 s for nodes
    that use node_runtime). So after `patience` seconds (longer than that 0.5 s and the
    ~0.1 s until nodes are named) a fresh participant is tried (the old one is shut down once
    the new one exists, so both get distinct ports). Where the participants cannot be
    counted, meeting any other node is enough. Gives up after `bound` seconds: somebody may
    just not announce.
    """
    import rclpy

    from ros2cli_lite.participants import everyone_met

    start = time.monotonic()
    attempt_start = start
    while True:
        met = everyone_met(node)
        if met is None:
            met = len(node.get_node_names_and_namespaces()) > 1
        if met:
            return context, node, True
        now = time.monotonic()
        if now - start >= bound:
            return context, node, False
        if now - attempt_start >= patience and bound - (now - start) > patience:
            node.destroy_node()
            new_context, new_node = make()
            rclpy.try_shutdown(context=context)
            context, node = new_context, new_node
            attempt_start = time.monotonic()
        time.sleep(0.01)


def settle_graph(node: Any, bound: float) -> bool:
    """Until `node` has met every participant on this host, knows their nodes' endpoints and
    the graph has stopped changing (as the daemon before its first answer), for at most
    `bound` seconds. Returns whether the graph settled."""
    from ros2cli_lite.participants import everyone_met

    start = time.monotonic()
    wait_until(lambda: everyone_met(node) is not False, bound)
    return wait_for_graph(node, settle=0.1, everyone_met=True,
                          bound=max(0.0, bound - (time.monotonic() - start)))


def spin_once(node: Any, timeout: float) -> None:
    """Process pending callbacks of `node` for at most `timeout` seconds."""
    stop_if_cli_left()
    executor = getattr(node, '_cli_executor', None)
    if executor is None:
        executor = _cli_executor_class()(context=node.context)
        executor.add_node(node)
        node._cli_executor = executor
    executor.spin_once(timeout_sec=timeout)


def stop_if_cli_left() -> None:
    """In the daemon, a KeyboardInterrupt once the CLI it runs the verb for has gone: its
    Ctrl-C ends the verb there too. Called by every wait of a verb."""
    from ros2cli_lite.daemon.proxy import session
    running_for = session()
    if running_for is not None and running_for.take_interrupt():
        raise KeyboardInterrupt


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
                   bound: float | None = None, everyone_met: bool = False) -> bool:
    """Let discovery run until the graph has stopped changing for `settle` seconds.

    Without a daemon a fresh node knows nothing: poll the graph (cheap, local caches) and return
    once it is stable and complete and, if given, `ready()` holds; never later than `bound`
    seconds. Complete means another node is known (unless `everyone_met`: every participant on
    the host is known, see participants.py, and the graph may be empty) and every node's
    endpoints have arrived (a node's name and its endpoints are discovered separately,
    sometimes far apart under load).
    The default bound (None) is 2 s for listings, 4 s while looking for something that may
    just not be discovered yet (a loaded machine can take that long); a verb passes its
    --spin-time. Returns whether `ready()` held.
    """
    from ros2cli_lite.daemon.proxy import session
    if bound is None:
        bound = 2.0 if ready is None else 4.0
    if session() is not None:
        settle = 0.0  # the daemon's participant: its graph settled long ago
    start = time.monotonic()
    own = node.get_fully_qualified_name()
    last = None
    changed = start
    while True:
        now = time.monotonic()
        snapshot = graph_snapshot(node)
        others = [(n, ns) for n, ns in snapshot[0] if full_node_name(n, ns) != own]
        complete = (everyone_met or bool(others)) and all(
            _has_endpoints(node, n, ns) for n, ns in others)
        snapshot = (*snapshot, complete)
        if snapshot != last:
            last, changed = snapshot, now
        ok = ready() if ready is not None else True
        if ok and complete and now - changed >= settle:
            return True
        if now - start >= bound:
            return ok
        stop_if_cli_left()
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
        stop_if_cli_left()
        time.sleep(step)
    return True
