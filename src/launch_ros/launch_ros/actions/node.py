"""Node: ExecuteProcess for a ROS node, with name, namespace, parameters and remappings.

The command is `<executable> [arguments] [--ros-args <ros_arguments>] --ros-args -r __node:=...`
and, once the launch context is known (`_perform_substitutions`), `-r __ns:=...`, the
parameters of SetParameter / SetParametersFromFile, the node's own parameters (a file per
dict, `-p name:=value` per Parameter) and the remapping rules (SetRemap's first).
"""

from __future__ import annotations

import os
import pathlib
import re
from tempfile import NamedTemporaryFile
from typing import TYPE_CHECKING, Any

import yaml
from launch.actions import ExecuteProcess
from launch.frontend import expose_action
from launch.logging import get_logger
from launch.substitutions import LocalSubstitution
from launch.utilities import (
    ensure_argument_type,
    normalize_to_list_of_substitutions,
    perform_substitutions,
)

from launch_ros.parameter_descriptions import Parameter, ParameterFile, ParameterValue
from launch_ros.substitutions import ExecutableInPackage
from launch_ros.utilities import (
    add_node_name,
    evaluate_parameters,
    get_node_name_count,
    make_namespace_absolute,
    normalize_parameters,
    normalize_remap_rules,
    prefix_namespace,
)

if TYPE_CHECKING:
    from collections.abc import Iterable

    from launch.frontend import Entity, Parser
    from launch.launch_context import LaunchContext
    from launch.some_substitutions_type import SomeSubstitutionsType

    from launch_ros.parameters_type import SomeParameters
    from launch_ros.remap_rule_type import SomeRemapRules

_NAME = re.compile(r'^[A-Za-z_][A-Za-z0-9_]*$')
_NAMESPACE = re.compile(r'^(/[A-Za-z_][A-Za-z0-9_]*)*$|^/$')


def _validate(name: str | None, namespace: str | None) -> None:
    """ValueError naming what is wrong, as rcl would refuse it later (less clearly)."""
    if name is not None and not _NAME.match(name):
        raise ValueError(f"node name '{name}' is invalid: use letters, digits and "
                         'underscores, not starting with a digit')
    if namespace is not None and not _NAMESPACE.match(namespace):
        raise ValueError(f"namespace '{namespace}' is invalid: use /-separated letters, "
                         'digits and underscores')


@expose_action('node')
class Node(ExecuteProcess):
    UNSPECIFIED_NODE_NAME = '<node_name_unspecified>'
    UNSPECIFIED_NODE_NAMESPACE = '<node_namespace_unspecified>'

    @staticmethod
    def parse_nested_parameters(params: list[Entity], parser: Parser) -> list[Any]:
        """<param> tags as Node's `parameters`: a file per `from`, a dict per `name` (nested
        <param>s make nested dicts)."""
        from launch.frontend import Entity, FrontendError
        from launch.frontend.type_utils import get_data_type_from_identifier

        def nested(entities: list[Entity]) -> dict[Any, Any]:
            result: dict[Any, Any] = {}
            for param in entities:
                text = param.get_attr('name')
                name = tuple(parser.parse_substitution(text))
                type_identifier = param.get_attr('type', data_type=None, optional=True)
                data_type = (None if type_identifier is None
                             else get_data_type_from_identifier(type_identifier))
                value = param.get_attr('value', data_type=data_type, optional=True)
                children = param.get_attr('param', data_type=list[Entity], optional=True)
                param.assert_entity_completely_parsed()
                if children and (value is not None or data_type is not None):
                    raise FrontendError(f"<param name='{text}'>: nested <param>s "
                                        'and a value or type are mutually exclusive')
                if children:
                    result[name] = nested(children)
                elif value is None:
                    raise FrontendError(f"<param name='{text}'> needs a value "
                                        'attribute or nested <param>s')
                else:
                    result[name] = ParameterValue(parser.parse_if_substitutions(value),
                                                  value_type=data_type)
            return result

        parameters: list[Any] = []
        for param in params:
            source = param.get_attr('from', optional=True)
            allow = param.get_attr('allow_substs', data_type=bool, optional=True)
            name = param.get_attr('name', optional=True)
            if source is not None and name is not None:
                raise FrontendError("<param>: 'name' and 'from' are mutually exclusive")
            if source is not None:
                param.assert_entity_completely_parsed()
                parameters.append(ParameterFile(
                    parser.parse_substitution(source),
                    allow_substs=parser.parse_substitution(allow) if isinstance(allow, str)
                    else bool(allow)))
            elif name is not None:
                if allow is not None:
                    raise FrontendError("<param>: 'allow_substs' goes only with 'from'")
                parameters.append(nested([param]))
            else:
                raise FrontendError("<param> needs a 'name' or a 'from' attribute")
        return parameters

    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        from launch.frontend import Entity
        # ExecuteProcess reads the process options (name, output, env, respawn, ...).
        _, kwargs = super().parse(entity, parser, ignore=['cmd'])
        for key, attribute in (('arguments', 'args'), ('ros_arguments', 'ros_args')):
            words = entity.get_attr(attribute, optional=True)
            if words is not None:
                kwargs[key] = cls._parse_cmdline(words, parser)
        for key, attribute in (('exec_name', 'exec_name'), ('package', 'pkg'),
                               ('namespace', 'namespace')):
            value = entity.get_attr(attribute, optional=True)
            if value is not None:
                kwargs[key] = parser.parse_substitution(value)
        kwargs['executable'] = parser.parse_substitution(entity.get_attr('exec'))
        remappings = entity.get_attr('remap', data_type=list[Entity], optional=True)
        if remappings is not None:
            kwargs['remappings'] = [(parser.parse_substitution(remap.get_attr('from')),
                                     parser.parse_substitution(remap.get_attr('to')))
                                    for remap in remappings]
            for remap in remappings:
                remap.assert_entity_completely_parsed()
        parameters = entity.get_attr('param', data_type=list[Entity], optional=True)
        if parameters is not None:
            kwargs['parameters'] = cls.parse_nested_parameters(parameters, parser)
        return cls, kwargs

    def __init__(self, *, executable: SomeSubstitutionsType,
                 package: SomeSubstitutionsType | None = None,
                 name: SomeSubstitutionsType | None = None,
                 namespace: SomeSubstitutionsType | None = None,
                 exec_name: SomeSubstitutionsType | None = None,
                 parameters: SomeParameters | None = None,
                 remappings: SomeRemapRules | None = None,
                 ros_arguments: Iterable[SomeSubstitutionsType] | None = None,
                 arguments: Iterable[SomeSubstitutionsType] | None = None,
                 **kwargs: Any) -> None:
        cmd: list[Any] = [executable if package is None
                          else ExecutableInPackage(package=package, executable=executable)]
        cmd += list(arguments or [])
        if ros_arguments is not None:
            cmd += ['--ros-args', *ros_arguments]
        cmd += ['--ros-args']
        if name is not None:
            cmd += ['-r', LocalSubstitution("ros_specific_arguments['name']",
                                            description='node name')]
        if parameters is not None:
            ensure_argument_type(parameters, list, 'parameters', 'Node')
            parameters = normalize_parameters(parameters)
        kwargs['name'] = exec_name
        super().__init__(cmd=cmd, **kwargs)
        self.__package = package
        self.__executable = executable
        self.__node_name = name
        self.__node_namespace = namespace
        self.__parameters = parameters
        self.__remappings = [] if remappings is None else list(normalize_remap_rules(remappings))
        self.__expanded_node_name = self.UNSPECIFIED_NODE_NAME
        self.__expanded_node_namespace = self.UNSPECIFIED_NODE_NAMESPACE
        self.__expanded_parameter_arguments: list[tuple[str, bool]] | None = None
        self.__expanded_remappings: list[tuple[str, str]] | None = None
        self.__final_node_name: str | None = None
        self.__substitutions_performed = False

    @property
    def node_package(self) -> Any:
        return self.__package

    @property
    def node_executable(self) -> Any:
        return self.__executable

    @property
    def node_name(self) -> str:
        if self.__final_node_name is None:
            raise RuntimeError("cannot access 'node_name' before executing action")
        return self.__final_node_name

    @property
    def expanded_node_namespace(self) -> str:
        return self.__expanded_node_namespace

    @property
    def expanded_remapping_rules(self) -> list[tuple[str, str]] | None:
        return self.__expanded_remappings

    def is_node_name_fully_specified(self) -> bool:
        return all(mark not in self.node_name for mark in (self.UNSPECIFIED_NODE_NAME,
                                                            self.UNSPECIFIED_NODE_NAMESPACE))

    def _extend_cmd(self, *parts: Any) -> None:
        self.cmd.extend(normalize_to_list_of_substitutions(part) for part in parts)

    def _perform_substitutions(self, context: LaunchContext) -> None:
        """Work out name, namespace, parameters and remappings, and extend the command."""
        if self.__substitutions_performed:
            return
        self.__substitutions_performed = True
        try:
            if self.__node_name is not None:
                self.__expanded_node_name = perform_substitutions(
                    context, normalize_to_list_of_substitutions(self.__node_name))
                _validate(self.__expanded_node_name, None)
            namespace = None if self.__node_namespace is None else perform_substitutions(
                context, normalize_to_list_of_substitutions(self.__node_namespace))
            namespace = make_namespace_absolute(prefix_namespace(
                context.launch_configurations.get('ros_namespace'), namespace))
            if namespace is not None:
                self.__expanded_node_namespace = namespace
                _validate(None, namespace)
                self._extend_cmd('-r', LocalSubstitution("ros_specific_arguments['ns']"))
        except Exception:
            get_logger(__name__).error(
                "Error while expanding or validating node name or namespace for "
                f"'package={self.__package}, executable={self.__executable}, "
                f"name={self.__node_name}, namespace={self.__node_namespace}':")
            raise
        self.__final_node_name = prefix_namespace(self.__expanded_node_namespace,
                                                  self.__expanded_node_name)
        self._add_parameters(context)
        self._add_remappings(context)

    def _add_parameters(self, context: LaunchContext) -> None:
        global_params = context.launch_configurations.get('global_params')
        if global_params is None and self.__parameters is None:
            return
        expanded: list[tuple[str, bool]] = []
        self.__expanded_parameter_arguments = expanded
        for item in global_params or ():
            if isinstance(item, tuple):  # SetParameter's (name, value)
                self._extend_cmd('-p', f'{item[0]}:={item[1]}')
            else:  # SetParametersFromFile's path
                path = os.path.abspath(item)
                if not os.path.isfile(path):
                    raise FileNotFoundError(f"parameters file '{path}' does not exist")
                expanded.append((path, True))
                self._extend_cmd('--params-file', path)
        for params in evaluate_parameters(context, self.__parameters or ()):
            if isinstance(params, dict):
                argument, is_file = self._create_params_file_from_dict(params), True
            elif isinstance(params, pathlib.Path):
                argument, is_file = str(params), True
            elif isinstance(params, Parameter):
                name, value = params.evaluate(context)
                argument, is_file = f'{name}:={yaml.dump(value)}', False
            else:
                raise RuntimeError(f'invalid normalized parameters {params!r}')
            if is_file and not os.path.isfile(argument):
                get_logger(__name__).warning(f'Parameter file path is not a file: {argument}')
                continue
            expanded.append((argument, is_file))
            self._extend_cmd('--params-file' if is_file else '-p', argument)

    def _add_remappings(self, context: LaunchContext) -> None:
        rules = list(context.launch_configurations.get('ros_remaps') or [])
        rules += [(perform_substitutions(context, list(src)),
                   perform_substitutions(context, list(dst))) for src, dst in self.__remappings]
        if not rules:
            return
        self.__expanded_remappings = rules
        for src, dst in rules:
            self._extend_cmd('-r', f'{src}:={dst}')

    def _create_params_file_from_dict(self, params: dict[str, Any]) -> str:
        """A launch_params_* file holding the dict's parameters, for this node or for all."""
        key = self.node_name if self.is_node_name_fully_specified() else '/**'
        with NamedTemporaryFile('w', prefix='launch_params_', delete=False) as handle:
            yaml.dump({key: {'ros__parameters': params}}, handle, default_flow_style=False)
            return handle.name

    def execute(self, context: LaunchContext) -> Any:
        self._perform_substitutions(context)
        ros_specific_arguments: dict[str, str] = {}
        if self.__node_name is not None:
            ros_specific_arguments['name'] = f'__node:={self.__expanded_node_name}'
        if self.__expanded_node_namespace != '':
            ros_specific_arguments['ns'] = f'__ns:={self.__expanded_node_namespace}'
        context.extend_locals({'ros_specific_arguments': ros_specific_arguments})
        result = super().execute(context)
        if self.is_node_name_fully_specified():
            add_node_name(context, self.node_name)
            count = get_node_name_count(context, self.node_name)
            if count > 1:
                get_logger(self.process_details.get('name', 'launch_ros')).warning(
                    f'there are now at least {count} nodes with the name {self.node_name} '
                    'created within this launch context')
        return result
