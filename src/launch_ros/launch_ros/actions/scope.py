"""Actions that set ROS settings for the nodes after them, in their GroupAction's scope."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from launch.action import Action
from launch.frontend.expose import expose_action
from launch.substitution import (
    SomeSubstitutionsType,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)

from launch_ros.actions.node import make_absolute, prefix_namespace
from launch_ros.parameter_descriptions import evaluate_value

if TYPE_CHECKING:
    from launch.frontend.entity import Entity
    from launch.frontend.parser import Parser
    from launch.launch_context import LaunchContext


def _text(context: LaunchContext, value: SomeSubstitutionsType) -> str:
    return perform_substitutions(context, normalize_to_list_of_substitutions(value))


@expose_action('push-ros-namespace')
class PushROSNamespace(Action):
    """Puts the following nodes (with relative namespaces) under this namespace."""

    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        kwargs = {'namespace': entity.get_substitutions('namespace', True)}
        return cls, {**kwargs, **cls.parse_condition(entity)}

    def __init__(self, namespace: SomeSubstitutionsType, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.namespace = namespace

    def execute(self, context: LaunchContext) -> None:
        namespace = _text(context, self.namespace)
        base = context.launch_configurations.get('ros_namespace')
        context.launch_configurations['ros_namespace'] = make_absolute(
            prefix_namespace(base, namespace) or '/')


PushRosNamespace = PushROSNamespace


@expose_action('set_parameter')
class SetParameter(Action):
    """A parameter given to every node after it (`-p name:=value`)."""

    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        kwargs = {'name': entity.get('name', required=True),
                  'value': entity.get_substitutions('value', True)}
        return cls, {**kwargs, **cls.parse_condition(entity)}

    def __init__(self, name: SomeSubstitutionsType, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.param_name = name
        self.value = value

    def execute(self, context: LaunchContext) -> None:
        value = evaluate_value(context, self.value)
        text = value if isinstance(value, str) else str(value).lower() \
            if isinstance(value, bool) else str(value)
        params = tuple(context.launch_configurations.get('global_params', ()))
        context.launch_configurations['global_params'] = (
            *params, (_text(context, self.param_name), text))


class SetParametersFromFile(Action):
    """A parameters file given to every node after it."""

    def __init__(self, filename: SomeSubstitutionsType, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.filename = filename

    def execute(self, context: LaunchContext) -> None:
        params = tuple(context.launch_configurations.get('global_params', ()))
        context.launch_configurations['global_params'] = (
            *params, _text(context, self.filename))


@expose_action('set_remap')
class SetRemap(Action):
    """A remapping rule given to every node after it."""

    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        kwargs = {'src': entity.get_substitutions('from', True),
                  'dst': entity.get_substitutions('to', True)}
        return cls, {**kwargs, **cls.parse_condition(entity)}

    def __init__(self, src: SomeSubstitutionsType, dst: SomeSubstitutionsType,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.src = src
        self.dst = dst

    def execute(self, context: LaunchContext) -> None:
        remaps = tuple(context.launch_configurations.get('ros_remaps', ()))
        context.launch_configurations['ros_remaps'] = (
            *remaps, (_text(context, self.src), _text(context, self.dst)))
