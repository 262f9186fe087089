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

An exposed action's tag must have been read completely: an attribute or nested tag that no
parse method read is an error, not silently ignored.
"""

from __future__ import annotations

import functools
import inspect
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from launch.action import Action
    from launch.frontend.entity import Entity
    from launch.frontend.parser import Parser
    from launch.substitution import Substitution

action_parse_methods: dict[str, Any] = {}
substitution_parse_methods: dict[str, Any] = {}


def _lookup(table: dict[str, Any], name: str) -> Any:
    # 'push-ros-namespace' and 'push_ros_namespace' are the same tag.
    for key in (name, name.replace('-', '_'), name.replace('_', '-')):
        if key in table:
            return table[key]
    return None


def instantiate_action(entity: Entity, parser: Parser) -> Action:
    method = _lookup(action_parse_methods, entity.type_name)
    if method is None:
        raise RuntimeError(f'Unrecognized entity of the type: {entity.type_name}')
    action_type, kwargs = method(entity, parser)
    return action_type(**kwargs)


def instantiate_substitution(type_name: str, args: Iterable[Any] | None = None
                             ) -> Substitution:
    method = _lookup(substitution_parse_methods, type_name)
    if method is None:
        raise RuntimeError(f'Unknown substitution: {type_name}')
    substitution_type, kwargs = method(list(args) if args is not None else [])
    return substitution_type(**kwargs)


def __expose_impl(name: str, table: dict[str, Any], kind: str) -> Callable[[Any], Any]:
    def register(exposed: Any) -> Any:
        if inspect.isclass(exposed):
            if not inspect.ismethod(getattr(exposed, 'parse', None)):
                raise RuntimeError(
                    "Did not find a class method called 'parse' in the class being decorated.")
            method = exposed.parse
        elif inspect.isfunction(exposed):
            method = exposed
        else:
            raise RuntimeError(f'Exposed {kind} parser for {name} is not a callable or a class '
                               'containing a parse method')
        if name in table and getattr(table[name], '__wrapped__', table[name]) != method:
            raise RuntimeError(f'Two {kind} parsing methods exposed with the same name: '
                               f'[{name}].')
        if kind == 'action':
            @functools.wraps(method)
            def checked(entity: Entity, parser: Parser) -> Any:
                result = method(entity, parser)
                entity.assert_entity_completely_parsed()
                return result
            table[name] = checked
        else:
            table[name] = method
        return exposed
    return register


def expose_action(name: str) -> Callable[[Any], Any]:
    """Register the decorated Action class (its `parse` classmethod) for the tag `name`."""
    return __expose_impl(name, action_parse_methods, 'action')


def expose_substitution(name: str) -> Callable[[Any], Any]:
    """Register the decorated Substitution class for `$(name ...)`."""
    return __expose_impl(name, substitution_parse_methods, 'substitution')


def one_argument(name: str, args: list[list[Substitution]]) -> list[Substitution]:
    """The single argument of `$(name arg)`; TypeError for any other count."""
    if len(args) != 1:
        raise TypeError(f'{name} substitution expects 1 argument')
    return args[0]
