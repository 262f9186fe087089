"""LifecycleNode: a Node whose state changes become StateTransition events and which makes
the transitions that ChangeState events ask of it (through its change_state service)."""

from __future__ import annotations

import threading
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.actions import OpaqueFunction
from launch.event_handler import EventHandler
from launch.logging import get_logger
from launch.some_substitutions_type import SomeSubstitutionsType

from launch_ros.actions.node import Node
from launch_ros.events.lifecycle import ChangeState, StateTransition
from launch_ros.ros_adapters import get_ros_adapter

if TYPE_CHECKING:
    import asyncio

    from launch.launch_context import LaunchContext

WAIT_STEP = 1.0  # seconds between checks whether the launch is shutting down meanwhile


class _InThread(Action):
    """Runs a blocking call on the loop's thread pool; the launch waits for it to end."""

    def __init__(self, function: Callable[[], None]) -> None:
        super().__init__()
        self._function = function
        self._future: asyncio.Future | None = None

    def execute(self, context: LaunchContext) -> None:
        self._future = context.asyncio_loop.run_in_executor(None, self._function)

    def get_asyncio_future(self) -> asyncio.Future | None:
        return self._future


class LifecycleNode(Node):
    def __init__(self, *, name: SomeSubstitutionsType, namespace: SomeSubstitutionsType,
                 **kwargs: Any) -> None:
        # '' is the root namespace (upstream's demo launch files pass it): the node's full
        # name must be known to reach its services.
        super().__init__(name=name, namespace='/' if namespace == '' else namespace, **kwargs)
        self.__logger = get_logger(__name__)
        self.__client: Any = None
        self.__adapter: Any = None
        self.__subscription: Any = None

    def execute(self, context: LaunchContext) -> Any:
        entities = super().execute(context)  # resolves node_name and starts the process
        if not self.is_node_name_fully_specified():
            raise RuntimeError('node_name unexpectedly incomplete for lifecycle node')
        from lifecycle_msgs.msg import TransitionEvent
        from lifecycle_msgs.srv import ChangeState as ChangeStateSrv
        self.__adapter = get_ros_adapter(context)
        node = self.__adapter.ros_node
        self.__subscription = node.create_subscription(
            TransitionEvent, f'{self.node_name}/transition_event',
            lambda msg: self._on_transition_event(context, msg), 10)
        self.__client = node.create_client(ChangeStateSrv, f'{self.node_name}/change_state')
        context.register_event_handler(EventHandler(
            matcher=lambda event: isinstance(event, ChangeState),
            entities=[OpaqueFunction(function=self._on_change_state_event)]))
        return entities

    def _on_transition_event(self, context: LaunchContext, msg: Any) -> None:
        # On the ROS thread: the event goes to the launch's loop.
        event = StateTransition(action=self, msg=msg)
        context.asyncio_loop.call_soon_threadsafe(context.emit_event_sync, event)

    def _on_change_state_event(self, context: LaunchContext) -> list[Action] | None:
        event: ChangeState = context.locals.event
        if not event.lifecycle_node_matcher(self):
            return None
        from lifecycle_msgs.srv import ChangeState as ChangeStateSrv
        request = ChangeStateSrv.Request()
        request.transition.id = event.transition_id
        return [_InThread(lambda: self._call_change_state(request, context))]

    def _ending(self, context: LaunchContext) -> bool:
        # A Shutdown event emitted by an action stops the ROS node before the context says
        # it is shutting down: no answer comes then.
        return context.is_shutdown or self.__adapter.is_shut_down

    def _call_change_state(self, request: Any, context: LaunchContext) -> None:
        service = self.__client.srv_name
        while not self.__client.wait_for_service(timeout_sec=WAIT_STEP):
            if self._ending(context):
                self.__logger.warning(f"Abandoning wait for the '{service}' service, due to "
                                      'shutdown.')
                return
        done = threading.Event()
        future = self.__client.call_async(request)
        future.add_done_callback(lambda _future: done.set())
        while not done.wait(WAIT_STEP):
            if self._ending(context):
                self.__logger.warning(f"Abandoning wait for the '{service}' service response, "
                                      'due to shutdown.')
                future.cancel()
                return
        if future.exception() is not None:
            raise future.exception()
        if not future.result().success:
            self.__logger.error(
                f"Failed to make transition "
                f"'{ChangeState.valid_transitions[request.transition.id]}' for LifecycleNode "
                f"'{self.node_name}'")
