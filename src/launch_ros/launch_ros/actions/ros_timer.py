"""ROSTimer: TimerAction timed by the launch's ROS node clock (sim time after SetUseSimTime)."""

from __future__ import annotations

import asyncio
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from launch.actions import TimerAction
from launch.event_handler import EventHandler
from launch.event_handlers import OnShutdown
from launch.events import TimerEvent
from launch.frontend import expose_action
from launch.utilities import ensure_argument_type
from launch.utilities.type_utils import normalize_typed_substitution, perform_typed_substitution

from launch_ros.ros_adapters import get_ros_node

if TYPE_CHECKING:
    from launch.frontend import Entity, Parser
    from launch.launch_context import LaunchContext
    from launch.launch_description_entity import LaunchDescriptionEntity
    from launch.some_substitutions_type import SomeSubstitutionsType


@expose_action('ros_timer')
class ROSTimer(TimerAction):
    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        # TimerAction reads the period and the nested actions.
        return cls, super().parse(entity, parser)[1]

    def __init__(self, *, period: float | SomeSubstitutionsType,
                 actions: Iterable[LaunchDescriptionEntity], **kwargs: Any) -> None:
        ensure_argument_type(period, (float, int, str, list, tuple, *_substitution_types()),
                             'period', 'ROSTimer')
        actions = list(actions)
        super().__init__(period=period, actions=actions, **kwargs)
        self.__period = normalize_typed_substitution(
            float(period) if isinstance(period, int) else period, float)
        self.__actions = actions
        self.__future: asyncio.Future | None = None
        self.__timer: Any = None

    def describe(self) -> str:
        return f'ROSTimer(period={self.__period}, actions=<actions>)'

    def get_asyncio_future(self) -> asyncio.Future | None:
        return self.__future

    def cancel(self) -> None:
        if self.__timer is not None:
            self.__timer.cancel()
        self._finish()

    def _finish(self) -> None:
        # The ROS timer is left alone: on shutdown it goes with the launch's node, which may
        # already be destroyed.
        if self.__future is not None and not self.__future.done():
            self.__future.set_result(None)

    def execute(self, context: LaunchContext) -> None:
        period = perform_typed_substitution(context, self.__period, float)
        loop = context.asyncio_loop
        self.__future = loop.create_future()
        context.register_event_handler(EventHandler(
            matcher=lambda event: isinstance(event, TimerEvent) and event.timer_action is self,
            entities=self.__actions, handle_once=True))
        context.register_event_handler(OnShutdown(on_shutdown=lambda *_: self._finish()))

        def fire() -> None:  # on the launch's loop
            if self.__future is not None and not self.__future.done():
                context.emit_event_sync(TimerEvent(timer_action=self))
                self.cancel()

        def start() -> None:
            # The ROS timer ticks on the adapter's thread: hand the firing to the launch's loop.
            if self.__future is not None and not self.__future.done():
                self.__timer = get_ros_node(context).create_timer(
                    period, lambda: loop.call_soon_threadsafe(fire))

        # Made once the actions after this one have run, as upstream does in a task: a
        # SetUseSimTime later in the same description then switches the clock first (a timer
        # made on system time restarts its period at the first /clock jump).
        loop.call_soon(start)
        return None


def _substitution_types() -> tuple[type, ...]:
    from launch.substitution import Substitution
    return (Substitution,)
