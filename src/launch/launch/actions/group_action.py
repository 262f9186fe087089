"""GroupAction: `<group>`, actions together; scoped (default), their configurations and
environment changes stay inside; not forwarding, they start from a clean slate too."""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.actions.pop_environment import PopEnvironment
from launch.actions.pop_launch_configurations import PopLaunchConfigurations
from launch.actions.push_environment import PushEnvironment
from launch.actions.push_launch_configurations import PushLaunchConfigurations
from launch.actions.reset_environment import ResetEnvironment
from launch.actions.reset_launch_configurations import ResetLaunchConfigurations, parse_keeps
from launch.actions.set_launch_configuration import SetLaunchConfiguration
from launch.frontend.expose import expose_action

if TYPE_CHECKING:
    from launch.frontend.entity import Entity
    from launch.frontend.parser import Parser
    from launch.launch_context import LaunchContext
    from launch.launch_description_entity import LaunchDescriptionEntity
    from launch.some_substitutions_type import SomeSubstitutionsType


@expose_action('group')
class GroupAction(Action):
    def __init__(self, actions: Iterable[Action], *, scoped: bool = True,
                 forwarding: bool = True,
                 launch_configurations: dict[SomeSubstitutionsType, SomeSubstitutionsType]
                 | None = None,
                 **left_over_kwargs: Any) -> None:
        super().__init__(**left_over_kwargs)
        self.__actions = actions
        self.__scoped = scoped
        self.__forwarding = forwarding
        self.__launch_configurations = launch_configurations or {}
        self.__actions_to_return: list[LaunchDescriptionEntity] | None = None

    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        _, kwargs = super().parse(entity, parser)
        for flag in ('scoped', 'forwarding'):
            value = entity.get_attr(flag, data_type=bool, optional=True)
            if value is not None:
                kwargs[flag] = value
        keeps = parse_keeps(entity, parser)
        if keeps is not None:
            kwargs['launch_configurations'] = keeps
        kwargs['actions'] = [parser.parse_action(child) for child in entity.children
                             if child.type_name != 'keep']
        return cls, kwargs

    def get_sub_entities(self) -> list[LaunchDescriptionEntity]:
        if self.__actions_to_return is None:
            actions = list(self.__actions)
            settings = [SetLaunchConfiguration(name, value)
                        for name, value in self.__launch_configurations.items()]
            if not self.__scoped:
                self.__actions_to_return = [*settings, *actions]
            elif self.__forwarding:
                self.__actions_to_return = [
                    PushLaunchConfigurations(), PushEnvironment(), *settings, *actions,
                    PopEnvironment(), PopLaunchConfigurations()]
            else:
                self.__actions_to_return = [
                    PushLaunchConfigurations(), PushEnvironment(), ResetEnvironment(),
                    ResetLaunchConfigurations(self.__launch_configurations), *actions,
                    PopEnvironment(), PopLaunchConfigurations()]
        return self.__actions_to_return

    def execute(self, context: LaunchContext) -> list[LaunchDescriptionEntity]:
        return self.get_sub_entities()
