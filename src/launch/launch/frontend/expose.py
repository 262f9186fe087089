"""The tag tables: each action or substitution registers itself (upstream's decorators).

    @expose_action('timer')
    class TimerAction(Action):
        @classmethod
        def parse(cls, entity, parser):        # -> (the class to build, its keyword arguments)
            ...

    @expose_substitution('var')
    class LaunchConfiguration(Substitution):
        @classmethod
        def parse(cls, data):                  # data: one list of substitutions per argument
            ...

Tags are stored with '-' read as '_' (`push-ros-namespace` is `push_ros_namespace`).
"""

from __future__ import annotations

import inspect
from collections.abc import Callable, Sequence
from typing import TYPE_CHECKING, Any

from launch.frontend.entity import FrontendError

if TYPE_CHECKING:
    from launch.action import Action
    from launch.frontend.entity import Entity
    from launch.frontend.parser import Parser
    from launch.substitution import Substitution

action_parse_methods: dict[str, Callable[..., tuple[type, dict[str, Any]]]] = {}
substitution_parse_methods: dict[str, Callable[..., tuple[type, dict[str, Any]]]] = {}


def _expose(name: str, table: dict[str, Callable[..., Any]], kind: str) -> Callable[[Any], Any]:
    key = name.replace('-', '_')

    def register(exposed: Any) -> Any:
        if inspect.isclass(exposed):
            method = getattr(exposed, 'parse', None)
            if not inspect.ismethod(method):
                raise RuntimeError(f"{exposed.__name__} exposed as the {kind} '{name}' has no "
                                   'classmethod parse')
        elif callable(exposed):
            method = exposed
        else:
            raise RuntimeError(f"the {kind} '{name}' is exposed with neither a class nor a "
                               'function')
        if key in table and table[key] != method:
            raise RuntimeError(f"two {kind}s exposed with the same name '{name}'")
        table[key] = method
        return exposed
    return register


def expose_action(name: str) -> Callable[[Any], Any]:
    """Register the decorated Action class (its `parse` classmethod) for the tag `name`."""
    return _expose(name, action_parse_methods, 'action')


def expose_substitution(name: str) -> Callable[[Any], Any]:
    """Register the decorated Substitution class for `$(name ...)`."""
    return _expose(name, substitution_parse_methods, 'substitution')


def instantiate_action(entity: Entity, parser: Parser) -> Action:
    method = action_parse_methods.get(entity.tag)
    if method is None:
        raise FrontendError(f'<{entity.tag}> is not supported by this launch '
                            '(see docs/launch.md)')
    action_type, kwargs = method(entity, parser)
    action = action_type(**kwargs)
    entity.check_all_used()  # an attribute nobody read is named, not ignored
    return action


def instantiate_substitution(name: str, args: Sequence[list[Substitution]]) -> Substitution:
    method = substitution_parse_methods.get(name.replace('-', '_'))
    if method is None:
        raise FrontendError(f"substitution '$({name} ...)' is not supported by this launch "
                            '(see docs/launch.md)')
    substitution_type, kwargs = method(list(args))
    return substitution_type(**kwargs)


def one_argument(name: str, args: Sequence[list[Substitution]]) -> list[Substitution]:
    """The single argument of `$(name arg)`; FrontendError for any other count."""
    if len(args) != 1:
        raise FrontendError(f'$({name} ...) takes one argument, got {len(args)}')
    return args[0]
