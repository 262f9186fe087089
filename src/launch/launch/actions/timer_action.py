"""TimerAction: actions run after a delay, with the launch configurations of when it started."""

from __future__ import annotations

import asyncio
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.actions.simple import PopLaunchConfigurations, PushLaunchConfigurations
from launch.event_handler import EventHandler
from launch.events import Shutdown, TimerEvent
from launch.frontend.expose import expose_action
from launch.substitution import (
    SomeSubstitutionsType,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)

if TYPE_CHECKING:
    from launch.frontend.entity import Entity
    from launch.frontend.parser import Parser
    from launch.launch_context import LaunchContext
    from launch.launch_description_entity import LaunchDescriptionEntity


class _RestoreConfigurations(Action):
    def __init__(self, configurations: dict[str, Any]) -> None:
        super().__init__()
        self.configurations = configurations

    def execute(self, context: LaunchContext) -> None:
        context.launch_configurations.clear()
        context.launch_configurations.update(self.configurations)


@expose_action('timer')
class TimerAction(Action):
    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        kwargs = {'period': entity.get_substitutions('period', True),
                  'actions': parser.parse_children(entity)}
        return cls, {**kwargs, **cls.parse_condition(entity)}

    def __init__(self, *, period: float | SomeSubstitutionsType,
                 actions: Iterable[LaunchDescriptionEntity], cancel_on_shutdown: bool = True,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.period = period if isinstance(period, (int, float)) else \
            normalize_to_list_of_substitutions(period)
        self.actions = list(actions)
        self.cancel_on_shutdown = cancel_on_shutdown
        self._future: asyncio.Future | None = None
        self._task: asyncio.Task | None = None

    def describe(self) -> str:
        return f'TimerAction(period={self.period})'

    def describe_conditional_sub_entities(self) -> list[tuple[str, list[Any]]]:
        return [(f'{self.period} seconds pass', self.actions)]

    def get_asyncio_future(self) -> asyncio.Future | None:
        return self._future

    def cancel(self) -> None:
        if self._task is not None:
            self._task.cancel()
        if self._future is not None and not self._future.done():
            self._future.set_result(None)

    def execute(self, context: LaunchContext) -> None:
        if isinstance(self.period, (int, float)):
            period = float(self.period)
        else:
            text = perform_substitutions(context, self.period)
            try:
                period = float(text)
            except ValueError:
                raise ValueError(f"TimerAction period must be a number of seconds, got '{text}'"
                                 ) from None
        captured = dict(context.launch_configurations)
        context.register_event_handler(EventHandler(
            matcher=lambda event: isinstance(event, TimerEvent) and event.timer_action is self,
            entities=[PushLaunchConfigurations(), _RestoreConfigurations(captured),
                      *self.actions, PopLaunchConfigurations()],
            handle_once=True))
        if self.cancel_on_shutdown:
            context.register_event_handler(_CancelOnShutdown(self))
        self._future = context.asyncio_loop.create_future()
        self._task = context.asyncio_loop.create_task(self._wait(context, period))
        return None

    async def _wait(self, context: LaunchContext, period: float) -> None:
        await asyncio.sleep(period)
        if self._future is not None and not self._future.done():
            context.emit_event_sync(TimerEvent(timer_action=self))
            self._future.set_result(None)


class _CancelOnShutdown(EventHandler):
    def __init__(self, timer: TimerAction) -> None:
        super().__init__(matcher=lambda event: isinstance(event, Shutdown), handle_once=True)
        self.timer = timer

    def handle(self, event: Any, context: LaunchContext) -> None:
        super().handle(event, context)
        self.timer.cancel()
        return None
