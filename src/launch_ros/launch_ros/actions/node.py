"""Node: ExecuteProcess for a ROS node, with name, namespace, parameters and remappings."""

from __future__ import annotations

import os
import re
import tempfile
from collections.abc import Iterable
from typing import TYPE_CHECKING, Any

import yaml
from launch.actions import ExecuteProcess
from launch.frontend.expose import expose_action
from launch.substitution import (
    SomeSubstitutionsType,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)
from launch.substitutions import LocalSubstitution

from launch_ros.parameter_descriptions import ParameterFile, evaluate_value
from launch_ros.substitutions import ExecutableInPackage

if TYPE_CHECKING:
    from launch.frontend.entity import Entity
    from launch.frontend.parser import Parser
    from launch.launch_context import LaunchContext

_NAME = re.compile(r'^[A-Za-z_][A-Za-z0-9_]*$')
_NAMESPACE = re.compile(r'^(/[A-Za-z_][A-Za-z0-9_]*)*$|^/$')


def prefix_namespace(base: str | None, namespace: str | None) -> str | None:
    """A namespace inside `base` (absolute ones stay as they are)."""
    if namespace is None or namespace == '':
        return base
    if base is None or namespace.startswith('/'):
        return namespace
    return base.rstrip('/') + '/' + namespace


def make_absolute(namespace: str | None) -> str | None:
    if namespace is None:
        return None
    return namespace if namespace.startswith('/') else '/' + namespace


@expose_action('node')
class Node(ExecuteProcess):
    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        from launch.frontend.entity import FrontendError
        parameters: list[Any] = []
        values: dict[str, Any] = {}
        for child in entity.children_of('param'):
            if child.get('from') is not None:
                parameters.append(child.get_substitutions('from'))
            else:
                value = child.get('value', required=True)
                values[child.get('name', required=True)] = (
                    value if isinstance(value, (bool, int, float, list))
                    else parser.parse_substitution(value))
            child.check_all_used()
        if values:
            parameters.insert(0, values)
        remappings = []
        for child in entity.children_of('remap'):
            remappings.append((child.get_substitutions('from', True),
                               child.get_substitutions('to', True)))
            child.check_all_used()
        for child in entity.children:
            if child.tag not in ('param', 'remap', 'env'):
                raise FrontendError(f'<node> cannot hold <{child.tag}>')
        namespace = entity.get('namespace', entity.get('ns'))
        kwargs = {'package': entity.get_substitutions('pkg'),
                  'executable': entity.get_substitutions('exec', True),
                  'name': entity.get_substitutions('name'),
                  'namespace': None if namespace is None else parser.parse_substitution(namespace),
                  'exec_name': entity.get_substitutions('exec_name'),
                  'arguments': entity.get_words('args'),
                  'ros_arguments': entity.get_words('ros_args'),
                  'parameters': parameters or None, 'remappings': remappings or None}
        return cls, {**kwargs, **cls.parse_process_options(entity)}

    UNSPECIFIED_NODE_NAME = '<node_name_unspecified>'
    UNSPECIFIED_NODE_NAMESPACE = '<node_namespace_unspecified>'

    def __init__(self, *, executable: SomeSubstitutionsType,
                 package: SomeSubstitutionsType | None = None,
                 name: SomeSubstitutionsType | None = None,
                 namespace: SomeSubstitutionsType | None = None,
                 exec_name: SomeSubstitutionsType | None = None,
                 parameters: Iterable[Any] | None = None,
                 remappings: Iterable[tuple[SomeSubstitutionsType, SomeSubstitutionsType]]
                 | None = None,
                 ros_arguments: Iterable[SomeSubstitutionsType] | None = None,
                 arguments: Iterable[SomeSubstitutionsType] | None = None,
                 **kwargs: Any) -> None:
        cmd: list[Any] = [ExecutableInPackage(executable=executable, package=package)
                          if package is not None else executable]
        cmd += list(arguments or [])
        if ros_arguments is not None:
            cmd += ['--ros-args', *ros_arguments]
        cmd += ['--ros-args']
        if name is not None:
            cmd += ['-r', LocalSubstitution("ros_specific_arguments['name']",
                                            description='node name')]
        if parameters is not None and not isinstance(parameters, (list, tuple)):
            raise TypeError("Node: 'parameters' must be a list (of dicts or file paths)")
        kwargs['name'] = exec_name
        super().__init__(cmd=cmd, **kwargs)
        self.node_package = package
        self.node_executable = executable
        self.__name = name
        self.__namespace = namespace
        self.__parameters = list(parameters or [])
        self.__remappings = list(remappings or [])
        self.__final_name: str | None = None

    @property
    def node_name(self) -> str:
        if self.__final_name is None:
            raise RuntimeError("cannot access 'node_name' before executing action")
        return self.__final_name

    def is_node_name_fully_specified(self) -> bool:
        return all(mark not in self.node_name for mark in (self.UNSPECIFIED_NODE_NAME,
                                                            self.UNSPECIFIED_NODE_NAMESPACE))

    def execute(self, context: LaunchContext) -> Any:
        ros_arguments: dict[str, str] = {}
        name = self.UNSPECIFIED_NODE_NAME
        if self.__name is not None:
            name = perform_substitutions(context, normalize_to_list_of_substitutions(
                self.__name))
            if not _NAME.match(name):
                raise ValueError(f"node name '{name}' is invalid: use letters, digits and "
                                 "underscores, not starting with a digit")
            ros_arguments['name'] = f'__node:={name}'
        namespace = None if self.__namespace is None else perform_substitutions(
            context, normalize_to_list_of_substitutions(self.__namespace))
        namespace = make_absolute(prefix_namespace(
            context.launch_configurations.get('ros_namespace'), namespace))
        extension: list[str] = []
        if namespace is not None:
            namespace = '/' + namespace.strip('/') if namespace.strip('/') else '/'
            if not _NAMESPACE.match(namespace):
                raise ValueError(f"namespace '{namespace}' is invalid: use /-separated "
                                 'letters, digits and underscores')
            ros_arguments['ns'] = f'__ns:={namespace}'
            extension += ['-r', f'__ns:={namespace}']
        self.__final_name = (namespace or self.UNSPECIFIED_NODE_NAMESPACE).rstrip('/') + \
            '/' + name
        for item in context.launch_configurations.get('global_params', ()):
            if isinstance(item, tuple):
                extension += ['-p', f'{item[0]}:={item[1]}']
            else:
                extension += ['--params-file', os.path.abspath(item)]
        for params in self.__parameters:
            extension += self._parameter_arguments(context, params)
        remaps = list(context.launch_configurations.get('ros_remaps', ()))
        remaps += [(perform_substitutions(context, normalize_to_list_of_substitutions(src)),
                    perform_substitutions(context, normalize_to_list_of_substitutions(dst)))
                   for src, dst in self.__remappings]
        for src, dst in remaps:
            extension += ['-r', f'{src}:={dst}']
        self.cmd.extend(normalize_to_list_of_substitutions(part) for part in extension)
        context.extend_locals({'ros_specific_arguments': ros_arguments})
        return super().execute(context)

    def _parameter_arguments(self, context: LaunchContext, params: Any) -> list[str]:
        if isinstance(params, dict):
            flat: dict[str, Any] = {}
            _flatten(context, params, '', flat)
            return ['--params-file', self._params_file(flat)]
        if isinstance(params, ParameterFile):
            path = params.evaluate(context)
        else:
            path = evaluate_value(context, params)
        if not isinstance(path, str):
            raise TypeError(f'Node parameters: expected a dict or a file path, got {params!r}')
        if not os.path.isfile(path):
            raise FileNotFoundError(f"parameters file '{path}' does not exist")
        return ['--params-file', path]

    def _params_file(self, params: dict[str, Any]) -> str:
        """Write dict parameters to a params file, as launch_ros does (launch_params_*)."""
        key = self.node_name if self.is_node_name_fully_specified() else '/**'
        with tempfile.NamedTemporaryFile('w', prefix='launch_params_', delete=False) as handle:
            yaml.safe_dump({key: {'ros__parameters': params}}, handle,
                           default_flow_style=False)
            return handle.name


def _flatten(context: LaunchContext, params: dict[Any, Any], prefix: str,
             out: dict[str, Any]) -> None:
    for key, value in params.items():
        name = perform_substitutions(context, normalize_to_list_of_substitutions(key))
        full = f'{prefix}{name}'
        if isinstance(value, dict):
            _flatten(context, value, full + '.', out)
        else:
            out[full] = evaluate_value(context, value)
