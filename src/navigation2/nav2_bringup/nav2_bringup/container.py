"""`nav2_container`: Nav2's servers as components of one process.

Upstream's bringup starts rclcpp_components' `component_container_isolated` as node
`nav2_container` and loads each server into it, each on its own executor thread, with its
own node arguments (NodeOptions) on top of the container's global ones (the params file,
use_sim_time). rclpy has no components, so this container is given the list on its command
line (JSON: name, 'module:main' of the server's executable, its own arguments), imports the
node class of each server's module, creates it with its arguments as the node's cli_args
(remaps such as cmd_vel:=cmd_vel_nav, a lifecycle manager's name and node_names) and spins
it, together with the nodes it creates itself (a server's costmap), on a multi-threaded
executor of its own thread. Ctrl-C: the lifecycle managers stop first, then the servers,
each bringing itself down as in its own process.
"""

from __future__ import annotations

import gc
import importlib
import inspect
import json
import sys
import threading
import time
from collections.abc import Callable
from typing import Any

import rclpy
import rclpy.node
from node_runtime.spinning import SIGNAL_CHECK_PERIOD, limit_shutdown, ros_session
from rclpy._rclpy_pybind11 import InvalidHandle
from rclpy.executors import ExternalShutdownException, MultiThreadedExecutor
from rclpy.node import Node
from tf2_ros import TransformListener

COMPONENT_THREADS = 4  # a server's goal may wait for its costmap's updates


def node_class(entry_point: str) -> type[Node]:
    """The node class that the executable's module defines (the one its main() creates)."""
    module = importlib.import_module(entry_point.split(':')[0])
    classes = [obj for obj in vars(module).values()
               if inspect.isclass(obj) and issubclass(obj, Node) and
               obj.__module__ == module.__name__]
    if len(classes) != 1:
        raise LookupError(f'{module.__name__} defines {len(classes)} node classes, not one')
    return classes[0]


def create_with_arguments(make: Callable[[], Node], arguments: list[str]) -> Node:
    """make(), with `arguments` as the cli_args of the first node it creates (the server's
    own node); nodes it creates inside (a costmap) get the container's global ones only."""
    original = rclpy.node.Node.__init__
    used = []

    def init(self: Node, *args: Any, **kwargs: Any) -> None:
        if not used:
            used.append(self)
            kwargs['cli_args'] = ['--ros-args', *arguments] if arguments else None
        original(self, *args, **kwargs)

    rclpy.node.Node.__init__ = init
    try:
        return make()
    finally:
        rclpy.node.Node.__init__ = original


def stop_listener_threads() -> None:
    """Join the servers' TF listener threads before rclpy's shutdown does.

    rclpy runs on-shutdown callbacks holding the context's lock, and a listener's thread asks
    context.ok() (the same lock) between spins: each join there waits out its 2 s timeout,
    which a process of one server affords and a container of ten does not.
    """
    listeners = [obj for obj in gc.get_objects() if isinstance(obj, TransformListener)]
    for listener in listeners:  # all told first: they wind down side by side
        listener._stop.set()
    deadline = time.monotonic() + 1.0
    for listener in listeners:
        thread = getattr(listener, 'dedicated_listener_thread', None)
        if thread is not None:
            thread.join(timeout=max(0.0, deadline - time.monotonic()))


class Component:
    """One server in the container: its node, the nodes it owns, its executor thread."""

    def __init__(self, description: dict, stop: threading.Event) -> None:
        self.name = description['name']
        cls = node_class(description['entry_point'])
        wants_stop = 'stop' in inspect.signature(cls.__init__).parameters
        self.node = create_with_arguments(
            lambda: cls(stop) if wants_stop else cls(), description.get('arguments', []))
        if hasattr(self.node, 'stop_event'):
            self.node.stop_event = stop
        self.executor = MultiThreadedExecutor(num_threads=COMPONENT_THREADS)
        self.executor.add_node(self.node)
        for value in vars(self.node).values():  # e.g. planner_server's global_costmap
            if isinstance(value, Node) and value is not self.node:
                self.executor.add_node(value)
        self.thread = threading.Thread(target=self._spin, name=self.name, daemon=True)

    def _spin(self) -> None:
        while rclpy.ok() and not self._stopped.is_set():
            try:
                self.executor.spin_once(timeout_sec=SIGNAL_CHECK_PERIOD)
            except ExternalShutdownException:
                return
            except InvalidHandle:
                # a transition destroyed a publisher or subscription while this thread
                # waited on it: the next wait set is made without it
                continue
            except Exception as error:  # one failed callback must not stop the server
                self.node.get_logger().error(f'Exception in {self.name}: {error!r}')

    def start(self, stopped: threading.Event) -> None:
        self._stopped = stopped
        self.thread.start()

    def stop(self) -> None:
        self.thread.join(timeout=1.0)
        self.executor.shutdown(timeout_sec=0.5)
        self.node.destroy_node()


def main(args: list[str] | None = None) -> int:
    argv = sys.argv if args is None else args
    plain = rclpy.utilities.remove_ros_args(argv)
    if len(plain) < 2:
        print('usage: nav2_container <components as JSON> [<container name>] [--ros-args ...]',
              file=sys.stderr)
        return 2
    try:
        descriptions = json.loads(plain[1])
    except json.JSONDecodeError as error:
        print(f'nav2_container: the components are not JSON: {error}', file=sys.stderr)
        return 2
    with ros_session(argv) as stop:
        container = Node(plain[2] if len(plain) > 2 else 'nav2_container')
        components = []
        for description in descriptions:
            try:
                components.append(Component(description, stop))
            except Exception as error:  # one bad component must not take the others down
                container.get_logger().error(
                    f"Failed to load component {description.get('name')}: {error}")
        for component in components:
            container.get_logger().info(f'Loaded node /{component.node.get_name()}')
        stopped = threading.Event()
        for component in components:
            component.start(stopped)
        try:
            while not stop.is_set() and rclpy.ok():
                stop.wait(SIGNAL_CHECK_PERIOD)
        finally:
            stopped.set()
            # the managers first: they must not drive servers that are going away
            for component in sorted(components, key=lambda c: 'lifecycle_manager' not in
                                    type(c.node).__module__):
                component.stop()
            container.destroy_node()
            stop_listener_threads()
            limit_shutdown()  # a fresh budget for rclpy's shutdown
    return 0


if __name__ == '__main__':
    sys.exit(main())
