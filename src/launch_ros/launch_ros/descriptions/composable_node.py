"""ComposableNode: a node to load into a component container (a description, not an action)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from launch.utilities import normalize_to_list_of_substitutions

from launch_ros.utilities import normalize_parameters, normalize_remap_rules

if TYPE_CHECKING:
    from launch.condition import Condition
    from launch.some_substitutions_type import SomeSubstitutionsType

    from launch_ros.parameters_type import SomeParameters
    from launch_ros.remap_rule_type import SomeRemapRules


class ComposableNode:
    def __init__(self, *, package: SomeSubstitutionsType, plugin: SomeSubstitutionsType,
                 name: SomeSubstitutionsType | None = None,
                 namespace: SomeSubstitutionsType | None = None,
                 parameters: SomeParameters | None = None,
                 remappings: SomeRemapRules | None = None,
                 extra_arguments: SomeParameters | None = None,
                 condition: Condition | None = None) -> None:
        self.__package = normalize_to_list_of_substitutions(package)
        self.__plugin = normalize_to_list_of_substitutions(plugin)
        self.__name = None if name is None else normalize_to_list_of_substitutions(name)
        self.__namespace = (None if namespace is None
                            else normalize_to_list_of_substitutions(namespace))
        self.__parameters = None if parameters is None else normalize_parameters(parameters)
        self.__remappings = list(normalize_remap_rules(remappings)) if remappings else None
        self.__extra_arguments = (normalize_parameters(extra_arguments) if extra_arguments
                                  else None)
        self.__condition = condition

    @property
    def package(self) -> Any:
        return self.__package

    @property
    def node_plugin(self) -> Any:
        return self.__plugin

    @property
    def node_name(self) -> Any:
        return self.__name

    @property
    def node_namespace(self) -> Any:
        return self.__namespace

    @property
    def parameters(self) -> Any:
        return self.__parameters

    @property
    def remappings(self) -> Any:
        return self.__remappings

    @property
    def extra_arguments(self) -> Any:
        return self.__extra_arguments

    def condition(self) -> Any:
        return self.__condition
