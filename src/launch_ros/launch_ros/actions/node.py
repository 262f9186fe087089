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

from launch_ros._launch_api import (
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
    from launch.frontend import Entity, Parser
    from launch.launch_context import LaunchContext

_NAME = re.compile(r'^[A-Za-z_][A-Za-z0-9_]*$')
_NAMESPACE = re.compile(r'^(/[A-Za-z_][A-Za-z0-9_]*)*$|^/$')


_TYPES = {'str': str, 'int': int, 'float': float, 'bool': bool, 'list_of_str': list[str],
          'list_of_int': list[int], 'list_of_float': list[float], 'list_of_bool': list[bool]}


def _parameter_value(param: Entity, parser: Parser) -> ParameterValue:
    """A <param value=...> as a ParameterValue: typed values (YAML launch files) as they are,
    text with its substitutions, `value-sep` splitting text into a list, `type` its type."""
    from launch.frontend import FrontendError
    type_name = param.get('type')
    if type_name is not None and type_name not in _TYPES:
        raise FrontendError(f"<param type='{type_name}'> is not one of "
                            f"{', '.join(sorted(_TYPES))}")
    value_type = None if type_name is None else _TYPES[type_name]
    if hasattr(param, 'get_attr'):
        # launch's upstream Entity API reads value-sep and types the value itself.
        value = param.get_attr('value', data_type=value_type, optional=True)
    else:
        value = param.get('value')
        separator = param.get('value-sep')
        if isinstance(value, str) and separator:
            value = [_yaml_scalar(item) if value_type is None else item
                     for item in value.split(separator)]
    if isinstance(value, list):
        value = [parser.parse_substitution(item) if isinstance(item, str) and '$(' in item
                 else item for item in value]
        return ParameterValue(value, value_type=value_type)
    if isinstance(value, str):
        return ParameterValue(parser.parse_substitution(value), value_type=value_type)
    return ParameterValue(value, value_type=value_type)


def _yaml_scalar(text: str) -> Any:
    """An item of a value-sep list read as YAML, kept as text if it is no scalar."""
    try:
        loaded = yaml.safe_load(text)
    except yaml.YAMLError:
        return text
    return loaded if isinstance(loaded, (bool, int, float, str)) else text


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
        from launch.frontend import FrontendError

        def nested(entities: list[Entity]) -> dict[Any, Any]:
            result: dict[Any, Any] = {}
            for param in entities:
                name = tuple(parser.parse_substitution(param.get('name', required=True)))
                children = param.children_of('param')
                value = param.get('value')
                if children and (value is not None or param.get('type') is not None):
                    raise FrontendError(f"<param name='{param.get('name')}'>: nested <param>s "
                                        'and a value or type are mutually exclusive')
                if children:
                    result[name] = nested(children)
                elif value is None:
                    raise FrontendError(f"<param name='{param.get('name')}'> needs a value "
                                        'attribute or nested <param>s')
                else:
                    result[name] = _parameter_value(param, parser)
                param.check_all_used()
            return result

        parameters: list[Any] = []
        for param in params:
            if param.get('from') is not None:
                if param.get('name') is not None:
                    raise FrontendError("<param>: 'name' and 'from' are mutually exclusive")
                allow = param.get('allow_substs')
                parameters.append(ParameterFile(
                    param.get_substitutions('from'),
                    allow_substs=False if allow is None else allow if isinstance(allow, bool)
                    else parser.parse_substitution(allow)))
                param.check_all_used()
            elif param.get('name') is not None:
                parameters.append(nested([param]))
            else:
                raise FrontendError("<param> needs a 'name' or a 'from' attribute")
        return parameters

    @classmethod
    def parse(cls, entity: Entity, parser: Parser) -> tuple[type, dict[str, Any]]:
        parameters = cls.parse_nested_parameters(entity.children_of('param'), parser)
        remappings = []
        for child in entity.children_of('remap'):
            remappings.append((child.get_substitutions('from', True),
                               child.get_substitutions('to', True)))
            child.check_all_used()
        namespace = entity.get('namespace', entity.get('ns'))
        kwargs = {'package': entity.get_substitutions('pkg'),
                  'executable': entity.get_substitutions('exec', True),
                  'name': entity.get_substitutions('name'),
                  'namespace': None if namespace is None else parser.parse_substitution(namespace),
                  'exec_name': entity.get_substitutions('exec_name'),
                  'arguments': entity.get_words('args'),
                  'ros_arguments': entity.get_words('ros_args'),
                  'parameters': parameters or None, 'remappings': remappings or None}
        # ExecuteProcess reads the process options (output, env, respawn, ...), as for any
        # process tag.
        return cls, {**kwargs, **ExecuteProcess.parse_process_options(entity)}

    def __init__(self, *, executable: Any, package: Any = None, name: Any = None,
                 namespace: Any = None, exec_name: Any = None, parameters: Any = None,
                 remappings: Any = None, ros_arguments: Any = None, arguments: Any = None,
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
