"""nav2_util::LifecycleNode in rclpy: the base of every Nav2 server.

What it adds to rclpy.lifecycle.Node, as upstream's: the "lifecycle node launched" notice,
the `autostart_node` and `bond_heartbeat_period` parameters, and a best-effort deactivate and
cleanup when the process stops while the node is up (upstream's rcl pre-shutdown callback),
then "Destroying". A transition the current state does not offer is refused with rclcpp's
line (node_runtime's RclcppLifecycleTransitions); an exception in a transition callback is
logged in one line instead of vanishing into rclpy's ERROR return.

There is no bond: PyPI has no `bond` package, so the servers do not heartbeat to the
lifecycle manager (docs/navigation.md).
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import Any

from lifecycle_msgs.msg import State as StateMsg
from node_runtime.rclcpp_parity import RclcppLifecycleTransitions
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.executors import MultiThreadedExecutor
from rclpy.lifecycle import Node, State, TransitionCallbackReturn

from nav2_util.parameters import declare_checked

NOTIFICATION = ('\n\t{name} lifecycle node launched. \n'
                '\tWaiting on external lifecycle transitions to activate\n'
                '\tSee https://design.ros2.org/articles/node_lifecycle.html for more information.')


class LifecycleNode(RclcppLifecycleTransitions, Node):
    """A managed node with Nav2's start-up notice, autostart and clean stop."""

    def __init__(self, node_name: str, namespace: str | None = None, **kwargs: Any) -> None:
        super().__init__(node_name, namespace=namespace, **kwargs)
        # The process's stop event (set by Ctrl-C/SIGTERM): destroy_node then says why it
        # cleans up, as upstream's pre-shutdown callback does.
        self.stop_event: threading.Event | None = None
        self.bond_heartbeat_period = declare_checked(self, 'bond_heartbeat_period', 0.1)
        autostart_node = declare_checked(self, 'autostart_node', False)
        self.get_logger().info(NOTIFICATION.format(name=self.get_name()))
        self._autostart_timer = self.create_timer(0.0, self._on_autostart) \
            if autostart_node else None

    def _on_autostart(self) -> None:
        self._autostart_timer.cancel()
        name = self.get_name()
        self.get_logger().info(f'Auto-starting node: {name}')
        if self.trigger_configure() != TransitionCallbackReturn.SUCCESS:
            self.get_logger().error(f'Auto-starting node {name} failed to configure!')
            return
        if self.trigger_activate() != TransitionCallbackReturn.SUCCESS:
            self.get_logger().error(f'Auto-starting node {name} failed to activate!')

    @property
    def state_id(self) -> int:
        return self._state_machine.current_state[0]

    def is_active(self) -> bool:
        return self.state_id == StateMsg.PRIMARY_STATE_ACTIVE

    def _LifecycleNodeMixin__execute_callback(self, current_state_id, previous_state):
        # rclpy turns an exception in on_configure & co. into ERROR without a word
        callback = self._callbacks.get(current_state_id)
        if callback is None:
            return TransitionCallbackReturn.SUCCESS
        try:
            return callback(previous_state)
        except Exception as error:  # any failure is the transition's failure
            self.get_logger().error(f'Caught exception in callback for transition: {error}')
            return TransitionCallbackReturn.ERROR

    def on_deactivate(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Deactivating')
        return super().on_deactivate(state)  # disables the lifecycle publishers

    def on_cleanup(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Cleaning up')
        self.release()
        return TransitionCallbackReturn.SUCCESS

    def on_shutdown(self, state: State) -> TransitionCallbackReturn:
        self.get_logger().info('Shutting down')
        self.release()
        return TransitionCallbackReturn.SUCCESS

    def release(self) -> None:
        """Destroy what on_configure made (at cleanup and at shutdown); servers override it."""

    def run_cleanups(self) -> None:
        """Bring an active or inactive node back to unconfigured (best effort)."""
        if self.state_id == StateMsg.PRIMARY_STATE_ACTIVE:
            self.trigger_deactivate()
        if self.state_id == StateMsg.PRIMARY_STATE_INACTIVE:
            self.trigger_cleanup()

    def destroy_node(self) -> None:
        if self.stop_event is not None and self.stop_event.is_set():
            self.get_logger().info(
                f'Running Nav2 LifecycleNode rcl preshutdown ({self.get_name()})')
        self.run_cleanups()
        self.get_logger().info('Destroying')
        super().destroy_node()


def run_server(make: Callable[[], LifecycleNode], args: list[str] | None = None, *,
               companions: Callable[[LifecycleNode], list[Any]] | None = None) -> int:
    """A Nav2 server's main(): the node spins until Ctrl-C or SIGTERM, then stops cleanly.

    `companions(node)` names nodes the server owns that must spin beside it (a server's
    Costmap2DROS): then all spin in one multi-threaded executor, so a goal callback can wait
    for the costmap's updates."""
    with ros_session(args) as stop:
        node = make()
        node.stop_event = stop
        executor = None
        if companions is not None:
            executor = MultiThreadedExecutor(num_threads=4)
            for companion in companions(node):
                executor.add_node(companion)
        spin_until_stopped(node, stop, executor)
    return 0
