"""`ros2 run nav2_lifecycle_manager lifecycle_manager`: Nav2's lifecycle manager.

It drives the managed nodes of `node_names` through their lifecycle services: configure
then activate in the given order (STARTUP, and at start with `autostart`), deactivate,
clean up and shut down in reverse order. `<name>/manage_nodes`
(nav2_msgs/srv/ManageLifecycleNodes) takes the commands, `<name>/is_active`
(std_srvs/srv/Trigger) tells whether the managed nodes are up. Log lines as upstream's
(its blue bold `message()` lines included).

Not here: bonds (PyPI has no `bond`; bond_timeout, bond_respawn_max_duration and
attempt_respawn_reconnection are accepted and have no effect) and the /diagnostics status.
"""

from __future__ import annotations

import enum
import sys
import threading

from lifecycle_msgs.msg import State, Transition
from nav2_msgs.srv import ManageLifecycleNodes
from nav2_util.lifecycle_service_client import LifecycleServiceClient, ServiceUnavailable
from nav2_util.parameters import declare_checked, warn_unknown_parameters
from node_runtime.spinning import ros_session, spin_until_stopped
from rclpy.callback_groups import MutuallyExclusiveCallbackGroup, ReentrantCallbackGroup
from rclpy.executors import MultiThreadedExecutor
from rclpy.node import Node
from rclpy.parameter import Parameter
from std_srvs.srv import Trigger

# transition -> (the state it ends in, upstream's label)
TRANSITIONS = {
    Transition.TRANSITION_CONFIGURE: (State.PRIMARY_STATE_INACTIVE, 'Configuring '),
    Transition.TRANSITION_CLEANUP: (State.PRIMARY_STATE_UNCONFIGURED, 'Cleaning up '),
    Transition.TRANSITION_ACTIVATE: (State.PRIMARY_STATE_ACTIVE, 'Activating '),
    Transition.TRANSITION_DEACTIVATE: (State.PRIMARY_STATE_INACTIVE, 'Deactivating '),
    Transition.TRANSITION_UNCONFIGURED_SHUTDOWN: (State.PRIMARY_STATE_FINALIZED,
                                                  'Shutting down '),
}
FORWARD = (Transition.TRANSITION_CONFIGURE, Transition.TRANSITION_ACTIVATE)


class NodeState(enum.Enum):
    UNCONFIGURED = 0
    INACTIVE = 1
    ACTIVE = 2
    FINALIZED = 3
    UNKNOWN = 4


class LifecycleManager(Node):
    def __init__(self, stop: threading.Event) -> None:
        super().__init__('lifecycle_manager')
        self._stop = stop
        self.get_logger().info('Creating')
        names = declare_checked(self, 'node_names', Parameter.Type.STRING_ARRAY)
        self._autostart = declare_checked(self, 'autostart', False)
        for name, default in (('bond_timeout', 4.0), ('bond_respawn_max_duration', 10.0),
                              ('attempt_respawn_reconnection', True)):
            declare_checked(self, name, default)
        warn_unknown_parameters(self)
        self.node_names: list[str] | None = None if names is None else list(names)
        self._lifecycle_clients: dict[str, LifecycleServiceClient] = {}
        self._managed_state = NodeState.UNCONFIGURED
        # One thread at a time through the commands (upstream's callback_group_); the clients'
        # answers arrive on other executor threads while a command waits for them.
        self._command_group = MutuallyExclusiveCallbackGroup()
        self._client_group = ReentrantCallbackGroup()
        self._init_timer = None
        if self.node_names is None:
            return
        self.create_service(ManageLifecycleNodes, f'{self.get_name()}/manage_nodes',
                            self._on_manage_nodes, callback_group=self._command_group)
        self.create_service(Trigger, f'{self.get_name()}/is_active', self._on_is_active,
                            callback_group=self._command_group)
        self._init_timer = self.create_timer(0.0, self._on_init, self._command_group)

    def has_parameter_override(self, name: str) -> bool:
        return name in self._parameter_overrides

    def message(self, text: str) -> None:
        self.get_logger().info(f'\x1b[34m\x1b[1m{text}\x1b[0m\x1b[0m')

    def _on_init(self) -> None:
        self._init_timer.cancel()
        self.message('Creating and initializing lifecycle service clients')
        try:
            for name in self.node_names:
                self._lifecycle_clients[name] = LifecycleServiceClient(
                    self, name, self._client_group, self._stop)
        except ServiceUnavailable:
            return  # stopping while a node never came up
        if self._autostart:
            self.startup()

    def _on_manage_nodes(self, request: ManageLifecycleNodes.Request,
                         response: ManageLifecycleNodes.Response
                         ) -> ManageLifecycleNodes.Response:
        commands = {
            ManageLifecycleNodes.Request.STARTUP: self.startup,
            ManageLifecycleNodes.Request.CONFIGURE: self.configure,
            ManageLifecycleNodes.Request.CLEANUP: self.cleanup,
            ManageLifecycleNodes.Request.RESET: self.reset,
            ManageLifecycleNodes.Request.SHUTDOWN: self.shutdown,
            ManageLifecycleNodes.Request.PAUSE: self.pause,
            ManageLifecycleNodes.Request.RESUME: self.resume,
        }
        command = commands.get(request.command)
        if command is None:
            self.get_logger().error(
                f'Unknown command {request.command}: allowed are 0 (STARTUP), 1 (PAUSE), '
                '2 (RESUME), 3 (RESET), 4 (SHUTDOWN), 5 (CONFIGURE), 6 (CLEANUP)')
            response.success = False
        else:
            response.success = command()
        return response

    def _on_is_active(self, _request: Trigger.Request,
                      response: Trigger.Response) -> Trigger.Response:
        response.success = self._managed_state == NodeState.ACTIVE
        return response

    def change_state_for_node(self, name: str, transition: int) -> bool:
        expected, label = TRANSITIONS[transition]
        self.message(label + name)
        client = self._lifecycle_clients.get(name)
        if client is None:  # after SHUTDOWN destroyed the clients, as upstream's
            raise ServiceUnavailable('no lifecycle client (the nodes were shut down)')
        if not client.change_state(transition) or client.get_state() != expected:
            self.get_logger().error(f'Failed to change state for node: {name}')
            return False
        return True

    def change_state_for_all_nodes(self, transition: int, hard_change: bool = False) -> bool:
        names = self.node_names if transition in FORWARD else list(reversed(self.node_names))
        for name in names:
            try:
                if not self.change_state_for_node(name, transition) and not hard_change:
                    return False
            except ServiceUnavailable as error:
                self.get_logger().error(
                    f'Failed to change state for node: {name}. Exception: {error}.')
                return False
        return True

    def startup(self) -> bool:
        self.message('Starting managed nodes bringup...')
        if not (self.change_state_for_all_nodes(Transition.TRANSITION_CONFIGURE)
                and self.change_state_for_all_nodes(Transition.TRANSITION_ACTIVATE)):
            self.get_logger().error('Failed to bring up all requested nodes. Aborting bringup.')
            self._managed_state = NodeState.UNKNOWN
            return False
        self.message('Managed nodes are active')
        self._managed_state = NodeState.ACTIVE
        return True

    def configure(self) -> bool:
        self.message('Configuring managed nodes...')
        if not self.change_state_for_all_nodes(Transition.TRANSITION_CONFIGURE):
            self.get_logger().error(
                'Failed to configure all requested nodes. Aborting bringup.')
            self._managed_state = NodeState.UNKNOWN
            return False
        self.message('Managed nodes are now configured')
        self._managed_state = NodeState.INACTIVE
        return True

    def cleanup(self) -> bool:
        self.message('Cleaning up managed nodes...')
        if not self.change_state_for_all_nodes(Transition.TRANSITION_CLEANUP):
            self.get_logger().error('Failed to cleanup all requested nodes. Aborting cleanup.')
            self._managed_state = NodeState.UNKNOWN
            return False
        self.message('Managed nodes have been cleaned up')
        self._managed_state = NodeState.UNCONFIGURED
        return True

    def shutdown(self) -> bool:
        self.message('Shutting down managed nodes...')
        self.message('Deactivate, cleanup, and shutdown nodes')
        self._managed_state = NodeState.FINALIZED
        for transition in (Transition.TRANSITION_DEACTIVATE, Transition.TRANSITION_CLEANUP,
                           Transition.TRANSITION_UNCONFIGURED_SHUTDOWN):
            self.change_state_for_all_nodes(transition)
        self.message('Destroying lifecycle service clients')
        # Forgotten, not destroyed: another executor thread may be waiting on them (rclpy
        # fails such a wait); they go with the node.
        self._lifecycle_clients.clear()
        self.message('Managed nodes have been shut down')
        return True

    def reset(self, hard_reset: bool = False) -> bool:
        self.message('Resetting managed nodes...')
        if not (self.change_state_for_all_nodes(Transition.TRANSITION_DEACTIVATE, hard_reset)
                and self.change_state_for_all_nodes(Transition.TRANSITION_CLEANUP, hard_reset)):
            if not hard_reset:
                self.get_logger().error('Failed to reset nodes: aborting reset')
                self._managed_state = NodeState.UNKNOWN
                return False
        self.message('Managed nodes have been reset')
        self._managed_state = NodeState.UNCONFIGURED
        return True

    def pause(self) -> bool:
        self.message('Pausing managed nodes...')
        if not self.change_state_for_all_nodes(Transition.TRANSITION_DEACTIVATE):
            self.get_logger().error('Failed to pause nodes: aborting pause')
            self._managed_state = NodeState.UNKNOWN
            return False
        self.message('Managed nodes have been paused')
        self._managed_state = NodeState.INACTIVE
        return True

    def resume(self) -> bool:
        self.message('Resuming managed nodes...')
        if not self.change_state_for_all_nodes(Transition.TRANSITION_ACTIVATE):
            self.get_logger().error('Failed to resume nodes: aborting resume')
            self._managed_state = NodeState.UNKNOWN
            return False
        self.message('Managed nodes are active')
        self._managed_state = NodeState.ACTIVE
        return True

    def destroy_node(self) -> None:
        if self._stop.is_set():
            self.get_logger().info(
                f'Running Nav2 LifecycleManager rcl preshutdown ({self.get_name()})')
        self.get_logger().info(f'Destroying {self.get_name()}')
        super().destroy_node()


def main(args: list[str] | None = None) -> int:
    with ros_session(args) as stop:
        manager = LifecycleManager(stop)
        if manager.node_names is None:
            if not manager.has_parameter_override('node_names'):  # else declare_checked said
                manager.get_logger().error(
                    "Parameter 'node_names' is not set: give the managed nodes' names, "
                    "e.g. -p node_names:=['map_server']")
            manager.destroy_node()
            return 1
        # three threads: a command, the clients' answers, and is_active waiting its turn
        spin_until_stopped(manager, stop, MultiThreadedExecutor(num_threads=3))
    return 0


if __name__ == '__main__':
    sys.exit(main())
