"""TimerAction: `<timer period=>`, actions visited once a period has passed.

A shutdown cancels the timer (unless cancel_on_shutdown is false), so a pending timer does not
hold the launch up. The actions see the locals of when the timer started.
"""

from __future__ import annotations

import asyncio
import collections.abc
import warnings
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.event_handler import EventHandler
from launch.events.shutdown import Shutdown
from launch.events.timer_event import TimerEvent
from launch.frontend.expose import expose_action
from launch.logging import get_logger
from launch.some_substitutions_type import SomeSubstitutionsType_types_tuple
from launch.utilities import ensure_argument_type, is_a_subclass
from launch.utilities.type_utils import normalize_typed_substitution, perform_typed_substitution

if TYPE_CHECKING:
    from launch.frontend.entity import Entity
    from launch.frontend.parser import Parser
    from launch.launch_context import LaunchContext
    from launch.launch_description_entity import LaunchDescriptionEntity
    from launch.some_substitutions_type import SomeSubstitutionsType


@expose_action('timer')
class TimerAction(Action):
    def __init__(self, *, period: float | SomeSubstitutionsType,
                 actions: Iterable[LaunchDescriptionEntity],
                 cancel_on_shutdown: bool | SomeSubstitutionsType = True, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        ensure_argument_type(period, [*SomeSubstitutionsType_types_tuple, float, int],
                             'period', 'TimerAction')
        ensure_argument_type(actions, collections.abc.Iterable, 'actions', 'TimerAction')
        if isinstance(period, str):
            period = float(period)
            warnings.warn("The parameter 'period' must be a float or substitution,passing a "
                          'string literal was deprecated', stacklevel=2)
        if isinstance(period, int) and not isinstance(period, bool):
            period = float(period)
        self.__period = normalize_typed_substitution(period, float)
        self.__actions = actions
        self.__cancel_on_shutdown = normalize_typed_substitution(cancel_on_shutdown, bool)
        self.__context_locals: dict[str, Any] = {}
        self.__canceled = False
        self._completed_future: asyncio.Future | None = None
        self._canceled_future: asyncio.Future | None = None

    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        kwargs['period'] = parser.parse_if_substitutions(
            entity.get_attr('period', data_type=float, can_be_str=True))
        kwargs['actions'] = [parser.parse_action(child) for child in entity.children]
        cancel = entity.get_attr('cancel_on_shutdown', optional=True, data_type=bool,
                                 can_be_str=True)
        if cancel is not None:
            kwargs['cancel_on_shutdown'] = parser.parse_if_substitutions(cancel)
        return cls, kwargs

    @property
    def period(self) -> Any:
        return self.__period

    @property
    def actions(self) -> Iterable[LaunchDescriptionEntity]:
        return self.__actions

    def describe(self) -> str:
        return f'TimerAction(period={self.__period}, actions=<actions>)'

    def describe_conditional_sub_entities(
            self) -> list[tuple[str, Iterable[LaunchDescriptionEntity]]]:
        return [(f'{self.__period} seconds pass without being canceled', self.__actions)]

    def handle(self, context: LaunchContext) -> Iterable[LaunchDescriptionEntity]:
        """The timer fired: its actions, with the locals of when it started."""
        context.extend_locals(self.__context_locals)
        return self.__actions

    def cancel(self) -> None:
        self.__canceled = True
        if self._canceled_future is not None and not self._canceled_future.done():
            self._canceled_future.set_result(True)

    async def _wait_to_fire_event(self, context: LaunchContext) -> None:
        assert self._canceled_future is not None and self._completed_future is not None
        period = perform_typed_substitution(context, self.__period, float)
        await asyncio.wait([self._canceled_future], timeout=period)
        if not self._canceled_future.done():
            await context.emit_event(TimerEvent(timer_action=self))
        self._completed_future.set_result(None)

    def execute(self, context: LaunchContext) -> None:
        from launch.actions.opaque_function import OpaqueFunction
        loop = context.asyncio_loop
        assert loop is not None
        self._completed_future = loop.create_future()
        self._canceled_future = loop.create_future()
        if self.__canceled:
            get_logger(__name__).debug(f'timer {self} not waiting: canceled before it started')
            self._completed_future.set_result(None)
            return None
        # One handler per context hands every TimerEvent to its timer.
        if not getattr(context, '_timer_event_handler_installed', False):
            context.register_event_handler(EventHandler(
                matcher=lambda event: is_a_subclass(event, TimerEvent),
                entities=OpaqueFunction(
                    function=lambda ctx: ctx.locals.event.timer_action.handle(ctx))))
            context._timer_event_handler_installed = True
        self.__context_locals = dict(context.get_locals_as_dict())
        loop.create_task(self._wait_to_fire_event(context))
        if perform_typed_substitution(context, self.__cancel_on_shutdown, bool):
            context.register_event_handler(EventHandler(
                matcher=lambda event: is_a_subclass(event, Shutdown),
                entities=OpaqueFunction(function=lambda ctx: self.cancel())))
        return None

    def get_asyncio_future(self) -> asyncio.Future | None:
        return self._completed_future
