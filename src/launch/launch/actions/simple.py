"""The small actions: configurations, environment, groups, logging, events, shutdown."""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.event import Event
from launch.event_handler import BaseEventHandler
from launch.frontend.expose import expose_action
from launch.logging import get_logger
from launch.substitution import (
    SomeSubstitutionsType,
    describe,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)

if TYPE_CHECKING:
    from launch.frontend.entity import Entity
    from launch.frontend.parser import Parser
    from launch.launch_context import LaunchContext
    from launch.launch_description_entity import LaunchDescriptionEntity


@expose_action('let')
class SetLaunchConfiguration(Action):
    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        kwargs = {'name': entity.get('name', required=True),
                  'value': entity.get_substitutions('value', required=True)}
        return cls, {**kwargs, **cls.parse_condition(entity)}

    def __init__(self, name: SomeSubstitutionsType, value: SomeSubstitutionsType,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)
        self.value = normalize_to_list_of_substitutions(value)

    def execute(self, context: LaunchContext) -> None:
        context.launch_configurations[perform_substitutions(context, self.name)] = \
            perform_substitutions(context, self.value)

    def describe(self) -> str:
        return f'SetLaunchConfiguration({describe(self.name)}, {describe(self.value)})'


class UnsetLaunchConfiguration(Action):
    def __init__(self, name: SomeSubstitutionsType, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)

    def execute(self, context: LaunchContext) -> None:
        context.launch_configurations.pop(perform_substitutions(context, self.name), None)


class PushLaunchConfigurations(Action):
    def execute(self, context: LaunchContext) -> None:
        context._push_launch_configurations()


class PopLaunchConfigurations(Action):
    def execute(self, context: LaunchContext) -> None:
        context._pop_launch_configurations()


class ResetLaunchConfigurations(Action):
    """Forget every launch configuration but the given ones (GroupAction(forwarding=False))."""

    def __init__(self, launch_configurations: dict | None = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.launch_configurations = launch_configurations or {}

    def execute(self, context: LaunchContext) -> None:
        kept = {perform_substitutions(context, normalize_to_list_of_substitutions(k)):
                perform_substitutions(context, normalize_to_list_of_substitutions(v))
                for k, v in self.launch_configurations.items()}
        context.launch_configurations.clear()
        context.launch_configurations.update(kept)


class PushEnvironment(Action):
    def execute(self, context: LaunchContext) -> None:
        context._push_environment()


class PopEnvironment(Action):
    def execute(self, context: LaunchContext) -> None:
        context._pop_environment()


@expose_action('set_env')
class SetEnvironmentVariable(Action):
    """Sets an environment variable for the processes started after it (in its scope)."""

    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        kwargs = {'name': entity.get_substitutions('name', True),
                  'value': entity.get_substitutions('value', True)}
        return cls, {**kwargs, **cls.parse_condition(entity)}

    def __init__(self, name: SomeSubstitutionsType, value: SomeSubstitutionsType,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)
        self.value = normalize_to_list_of_substitutions(value)

    def execute(self, context: LaunchContext) -> None:
        context.environment[perform_substitutions(context, self.name)] = \
            perform_substitutions(context, self.value)

    def describe(self) -> str:
        return f'SetEnvironmentVariable({describe(self.name)}, {describe(self.value)})'


@expose_action('unset_env')
class UnsetEnvironmentVariable(Action):
    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        kwargs = {'name': entity.get_substitutions('name', True)}
        return cls, {**kwargs, **cls.parse_condition(entity)}

    def __init__(self, name: SomeSubstitutionsType, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)

    def execute(self, context: LaunchContext) -> None:
        context.environment.pop(perform_substitutions(context, self.name), None)


class AppendEnvironmentVariable(Action):
    def __init__(self, name: SomeSubstitutionsType, value: SomeSubstitutionsType, *,
                 prepend: bool = False, separator: str = ':', **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = normalize_to_list_of_substitutions(name)
        self.value = normalize_to_list_of_substitutions(value)
        self.prepend = prepend
        self.separator = separator

    def execute(self, context: LaunchContext) -> None:
        name = perform_substitutions(context, self.name)
        value = perform_substitutions(context, self.value)
        old = context.environment.get(name)
        if old:
            value = value + self.separator + old if self.prepend else old + self.separator + value
        context.environment[name] = value


@expose_action('group')
class GroupAction(Action):
    """Actions run together; scoped (default) keeps their configurations and environment in."""

    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        keep = {child.get('name', required=True): child.get_substitutions('value', required=True)
                for child in entity.children_of('keep')}
        actions = [parser.parse_action(child) for child in entity.children if child.tag != 'keep']
        kwargs = {'actions': actions, 'scoped': entity.get_bool('scoped', True),
                  'forwarding': entity.get_bool('forwarding', True),
                  'launch_configurations': keep or None}
        return cls, {**kwargs, **cls.parse_condition(entity)}

    def __init__(self, actions: Iterable[Action], *, scoped: bool = True,
                 forwarding: bool = True, launch_configurations: dict | None = None,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.actions = list(actions)
        self.scoped = scoped
        self.forwarding = forwarding
        self.launch_configurations = launch_configurations or {}

    def get_sub_entities(self) -> list[Action]:
        return self.actions

    def describe_sub_entities(self) -> list[LaunchDescriptionEntity]:
        return list(self.actions)

    def execute(self, context: LaunchContext) -> list[LaunchDescriptionEntity]:
        settings: list[Action] = [SetLaunchConfiguration(k, v)
                                  for k, v in self.launch_configurations.items()]
        if not self.scoped:
            return [*settings, *self.actions]
        if not self.forwarding:
            settings = [ResetLaunchConfigurations(self.launch_configurations)]
        return [PushLaunchConfigurations(), PushEnvironment(), *settings, *self.actions,
                PopEnvironment(), PopLaunchConfigurations()]


@expose_action('log')
class LogInfo(Action):
    """Logs a message as `[INFO] [launch.user]: ...`."""

    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        kwargs = {'msg': entity.get_substitutions('message', True)}
        return cls, {**kwargs, **cls.parse_condition(entity)}

    def __init__(self, *, msg: SomeSubstitutionsType, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.msg = normalize_to_list_of_substitutions(msg)

    def execute(self, context: LaunchContext) -> None:
        get_logger('launch.user').info(perform_substitutions(context, self.msg))

    def describe(self) -> str:
        return f'LogInfo({describe(self.msg)})'


class EmitEvent(Action):
    def __init__(self, *, event: Event, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        if not isinstance(event, Event):
            raise TypeError(f'EmitEvent needs an Event, got {type(event).__name__}')
        self.event = event

    def execute(self, context: LaunchContext) -> None:
        context.emit_event_sync(self.event)

    def describe(self) -> str:
        return f'EmitEvent({type(self.event).__name__})'


@expose_action('shutdown')
class Shutdown(EmitEvent):
    """Shuts the launch down (every process gets SIGINT, then SIGTERM, then SIGKILL)."""

    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        kwargs = {'reason': entity.get_substitutions('reason') or 'reason not given'}
        return cls, {**kwargs, **cls.parse_condition(entity)}

    def __init__(self, *, reason: SomeSubstitutionsType = 'reason not given',
                 **kwargs: Any) -> None:
        from launch.events import Shutdown as ShutdownEvent
        self.reason = normalize_to_list_of_substitutions(reason)
        super().__init__(event=ShutdownEvent(), **kwargs)

    def execute(self, context: LaunchContext) -> None:
        from launch.events import Shutdown as ShutdownEvent
        context.emit_event_sync(ShutdownEvent(reason=perform_substitutions(context,
                                                                           self.reason)))


class RegisterEventHandler(Action):
    def __init__(self, event_handler: BaseEventHandler, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        if not isinstance(event_handler, BaseEventHandler):
            raise TypeError('RegisterEventHandler needs an event handler, got '
                            f'{type(event_handler).__name__}')
        self.event_handler = event_handler

    def execute(self, context: LaunchContext) -> None:
        context.register_event_handler(self.event_handler)

    def describe_conditional_sub_entities(self) -> list[tuple[str, list[Any]]]:
        text, entities = self.event_handler.describe()
        return [(text, entities)] if entities else []

    def describe(self) -> str:
        return f'RegisterEventHandler({self.event_handler.describe()[0]})'


class UnregisterEventHandler(Action):
    def __init__(self, event_handler: BaseEventHandler, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.event_handler = event_handler

    def execute(self, context: LaunchContext) -> None:
        context.unregister_event_handler(self.event_handler)


class OpaqueFunction(Action):
    """Calls function(context, *args, **kwargs); what it returns is visited next."""

    def __init__(self, *, function: Callable[..., Any], args: Iterable[Any] | None = None,
                 kwargs: dict[str, Any] | None = None, **action_kwargs: Any) -> None:
        super().__init__(**action_kwargs)
        if not callable(function):
            raise TypeError('OpaqueFunction needs a callable function')
        self.function = function
        self.args = list(args or [])
        self.kwargs = dict(kwargs or {})

    def execute(self, context: LaunchContext) -> Any:
        return self.function(context, *self.args, **self.kwargs)
