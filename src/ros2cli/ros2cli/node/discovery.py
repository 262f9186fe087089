"""Meeting the graph: how a fresh node (the CLI's, the daemon's, a recorder's) learns who is
there before it answers, and the bounded waits on the graph every verb uses.

How long discovery may take is passed in (`bound`, a verb's --spin-time), never global.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from typing import Any

from ros2cli.names import full_node_name
from ros2cli.verb_context import VerbContext


def meet_graph(name: str, bound: float) -> tuple[Any, Any, bool]:
    """(a fresh context, a node in it, whether it met every participant on this host within
    `bound` seconds): the daemon's, which must not answer before it has."""
    context, node = make_node(name)
    # Never replaced: the others answer a newcomer at their next periodic announcement (every
    # 0.5 s for our nodes), so a fresh participant would only start that wait anew.
    return meet_graph_replacing(context, node, lambda: make_node(name), patience=bound, bound=bound)


def meet_graph_made(make: Callable[[], tuple[Any, Any]], bound: float = 1.8
                    ) -> tuple[Any, Any, bool]:
    """(a context, its node, whether it met every participant on this host within `bound`
    seconds): `make()` gives a fresh context and node, called again for a fresh participant
    when the first is not met quickly (as cli_node's). For a node of another package that
    must see what is already there before it decides (the recorder's)."""
    context, node = make()
    return meet_graph_replacing(context, node, make, bound=bound)


def make_node(name: str) -> tuple[Any, Any]:
    """(a fresh context, a node in it offering no services): the CLI's and the daemon's."""
    import rclpy
    from rclpy.context import Context

    context = Context()
    rclpy.init(args=[], context=context)
    return context, create_node(name, context)


def create_node(name: str, context: Any) -> Any:
    import rclpy
    from rclpy.parameter import Parameter

    # No parameter or type-description services: the CLI node offers nothing to the graph.
    return rclpy.create_node(
        name, context=context, start_parameter_services=False,
        parameter_overrides=[Parameter('start_type_description_service', value=False)])


def meet_graph_replacing(context: Any, node: Any, make: Callable[[], tuple[Any, Any]],
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

    from ros2cli.node.participants import everyone_met

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
    from ros2cli.node.participants import everyone_met

    start = time.monotonic()
    wait_until(lambda: everyone_met(node) is not False, bound)
    return wait_for_graph(node, settle=0.1, everyone_met=True,
                          bound=max(0.0, bound - (time.monotonic() - start)))


def graph_snapshot(node: Any) -> tuple:
    return (
        tuple(sorted(node.get_node_names_and_namespaces())),
        tuple((n, tuple(t)) for n, t in node.get_topic_names_and_types()),
        tuple((n, tuple(t)) for n, t in node.get_service_names_and_types()),
    )


def wait_for_graph(node: Any, ready: Callable[[], bool] | None = None, settle: float = 0.4,
                   bound: float | None = None, everyone_met: bool = False,
                   context: VerbContext | None = None) -> bool:
    """Let discovery run until the graph has stopped changing for `settle` seconds.

    Without a daemon a fresh node knows nothing: poll the graph (cheap, local caches) and return
    once it is stable and complete and, if given, `ready()` holds; never later than `bound`
    seconds. Complete means another node is known (unless `everyone_met`: every participant on
    the host is known, see participants.py, and the graph may be empty) and every node's
    endpoints have arrived (a node's name and its endpoints are discovered separately,
    sometimes far apart under load).
    The default bound (None) is 2 s for listings, 4 s while looking for something that may
    just not be discovered yet (a loaded machine can take that long); a verb passes its
    --spin-time. Returns whether `ready()` held. A verb passes its `context`: in the daemon
    the wait ends when its CLI leaves, and needs no settling.
    """
    if bound is None:
        bound = 2.0 if ready is None else 4.0
    if context is not None and context.in_daemon:
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
        if context is not None:
            context.check_cancelled()
        time.sleep(0.02)


def _has_endpoints(node: Any, name: str, namespace: str) -> bool:
    """Whether a node's publishers or services are known; False once it has left the graph."""
    from rclpy._rclpy_pybind11 import NodeNameNonExistentError
    try:
        return bool(node.get_publisher_names_and_types_by_node(name, namespace)
                    or node.get_service_names_and_types_by_node(name, namespace))
    except NodeNameNonExistentError:  # it left between listing the names and asking for this
        return False


def wait_until(predicate: Callable[[], bool], timeout: float, step: float = 0.02,
               context: VerbContext | None = None) -> bool:
    """Until `predicate()` holds, for at most `timeout` seconds; whether it held. A verb passes
    its `context`: in the daemon the wait ends when its CLI leaves."""
    deadline = time.monotonic() + timeout
    while not predicate():
        if time.monotonic() >= deadline:
            return False
        if context is not None:
            context.check_cancelled()
        time.sleep(step)
    return True
