"""XML and YAML launch files: parsed into the same actions a Python launch file builds.

Both formats become a tree of `_Entity` (a tag, its attributes, its children); one parser
turns that tree into actions. Substitutions use upstream's `$(name args...)` syntax.
What a file uses that is not here fails with one line naming the tag, attribute or
substitution.
"""

from __future__ import annotations

import xml.etree.ElementTree as ElementTree
from collections.abc import Callable
from typing import Any

import yaml

from launch.action import Action
from launch.launch_description import LaunchDescription
from launch.substitution import Substitution, TextSubstitution


class FrontendError(ValueError):
    pass


class _Entity:
    def __init__(self, tag: str, attributes: dict[str, Any], children: list[_Entity]) -> None:
        self.tag = tag.replace('-', '_')
        self.attributes = attributes
        self.children = children
        self._used: set[str] = set()

    def get(self, name: str, default: Any = None, required: bool = False) -> Any:
        self._used.add(name)
        if name in self.attributes:
            return self.attributes[name]
        if required:
            raise FrontendError(f"<{self.tag}> needs the attribute '{name}'")
        return default

    def check_all_used(self) -> None:
        unused = sorted(set(self.attributes) - self._used)
        if unused:
            raise FrontendError(f"<{self.tag}>: attribute '{unused[0]}' is not supported "
                                'by this launch (see docs/launch.md)')


# -- reading files --------------------------------------------------------------------------
def _from_xml(element: ElementTree.Element) -> _Entity:
    return _Entity(element.tag, dict(element.attrib), [_from_xml(child) for child in element])


_YAML_LIST_CHILDREN = {'arg', 'remap', 'param', 'env', 'keep'}


def _from_yaml(tag: str, body: Any) -> _Entity:
    if isinstance(body, list):  # e.g. `group:` directly followed by its actions
        return _Entity(tag, {}, [_from_yaml_item(item) for item in body])
    if not isinstance(body, dict):
        raise FrontendError(f"'{tag}' must hold a mapping of attributes, got {body!r}")
    attributes: dict[str, Any] = {}
    children: list[_Entity] = []
    for key, value in body.items():
        if key == 'children':
            children += [_from_yaml_item(item) for item in value or []]
        elif key in _YAML_LIST_CHILDREN and isinstance(value, list):
            children += [_from_yaml(key, item) for item in value]
        else:
            attributes[key] = value
    return _Entity(tag, attributes, children)


def _from_yaml_item(item: Any) -> _Entity:
    if not isinstance(item, dict) or len(item) != 1:
        raise FrontendError(f'each launch entry must be one action (e.g. `- node: ...`), got '
                            f'{item!r}')
    ((tag, body),) = item.items()
    return _from_yaml(str(tag), body)


def load_frontend_file(path: str, kind: str) -> LaunchDescription:
    if kind == 'xml':
        try:
            root = _from_xml(ElementTree.parse(path).getroot())
        except ElementTree.ParseError as error:
            raise FrontendError(f'invalid XML: {error}') from None
    else:
        with open(path, encoding='utf-8') as handle:
            try:
                data = yaml.safe_load(handle)
            except yaml.YAMLError as error:
                raise FrontendError(f'invalid YAML: {error}'.replace('\n', ' ')) from None
        if not isinstance(data, dict) or 'launch' not in data:
            raise FrontendError("a YAML launch file starts with 'launch:'")
        root = _Entity('launch', {}, [_from_yaml_item(i) for i in data['launch'] or []])
    if root.tag != 'launch':
        raise FrontendError(f'the root element must be <launch>, got <{root.tag}>')
    return LaunchDescription(_parse_children(root))


# -- substitutions: "$(var name)", "$(find-pkg-share pkg)/launch/x.py", ... -------------------
def parse_substitutions(text: Any) -> list[Substitution]:
    if isinstance(text, bool):
        text = str(text).lower()
    text = str(text)
    return _parse_text(text, 0, stop=None)[0]


def _parse_text(text: str, i: int, stop: str | None) -> tuple[list[Substitution], int]:
    parts: list[Substitution] = []
    literal = ''
    while i < len(text):
        if text.startswith('$(', i):
            if literal:
                parts.append(TextSubstitution(text=literal))
                literal = ''
            sub, i = _parse_call(text, i + 2)
            parts.append(sub)
            continue
        if stop is not None and text[i] in stop:
            break
        literal += text[i]
        i += 1
    if literal:
        parts.append(TextSubstitution(text=literal))
    return parts, i


def _parse_call(text: str, i: int) -> tuple[Substitution, int]:
    start = i
    while i < len(text) and not text[i].isspace() and text[i] != ')':
        i += 1
    name = text[start:i]
    args: list[list[Substitution]] = []
    while True:
        while i < len(text) and text[i].isspace():
            i += 1
        if i >= len(text):
            raise FrontendError(f"unterminated substitution '$({text[start:]}'")
        if text[i] == ')':
            i += 1
            break
        if text[i] in '\'"':
            quote = text[i]
            arg, i = _parse_text(text, i + 1, stop=quote)
            i += 1
        else:
            arg, i = _parse_text(text, i, stop=' \t\n)')
        args.append(arg)
    return _make_substitution(name, args), i


def _make_substitution(name: str, args: list[list[Substitution]]) -> Substitution:
    from launch import substitutions as s

    def one() -> list[Substitution]:
        if len(args) != 1:
            raise FrontendError(f'$({name} ...) takes one argument, got {len(args)}')
        return args[0]

    if name == 'var':
        if len(args) == 2:
            return s.LaunchConfiguration(args[0], default=args[1])
        return s.LaunchConfiguration(one())
    if name == 'env':
        return s.EnvironmentVariable(args[0], default_value=args[1] if len(args) > 1 else None)
    if name == 'eval':
        return s.PythonExpression(one())
    if name == 'find-exec':
        return s.FindExecutable(name=one())
    if name == 'dirname':
        return s.ThisLaunchFileDir()
    if name == 'filename':
        return s.ThisLaunchFile()
    if name == 'anon':
        return s.AnonName(one())
    if name == 'command':
        return s.Command(args[0], on_stderr=args[1] if len(args) > 1 else 'fail')
    if name in ('find-pkg-share', 'find-pkg-prefix', 'exec-in-pkg'):
        import launch_ros.substitutions as r
        if name == 'exec-in-pkg':
            return r.ExecutableInPackage(executable=args[0], package=args[1])
        return (r.FindPackageShare if name == 'find-pkg-share' else r.FindPackagePrefix)(one())
    raise FrontendError(f"substitution '$({name} ...)' is not supported by this launch "
                        '(see docs/launch.md)')


# -- actions ----------------------------------------------------------------------------------
def _bool(entity: _Entity, name: str, default: bool) -> bool:
    value = entity.get(name)
    if value is None:
        return default
    if isinstance(value, bool):
        return value
    if str(value).lower() in ('true', '1'):
        return True
    if str(value).lower() in ('false', '0'):
        return False
    raise FrontendError(f"<{entity.tag} {name}=...> must be true or false, got '{value}'")


def _condition(entity: _Entity) -> dict[str, Any]:
    from launch.conditions import IfCondition, UnlessCondition
    if_text, unless_text = entity.get('if'), entity.get('unless')
    if if_text is not None and unless_text is not None:
        raise FrontendError(f"<{entity.tag}> cannot have both 'if' and 'unless'")
    if if_text is not None:
        return {'condition': IfCondition(parse_substitutions(if_text))}
    if unless_text is not None:
        return {'condition': UnlessCondition(parse_substitutions(unless_text))}
    return {}


def _subs(entity: _Entity, name: str, required: bool = False) -> list[Substitution] | None:
    value = entity.get(name, required=required)
    return None if value is None else parse_substitutions(value)


def _children(entity: _Entity, tag: str) -> list[_Entity]:
    return [child for child in entity.children if child.tag == tag]


def _parse_children(entity: _Entity) -> list[Action]:
    return [_parse_action(child) for child in entity.children]


def _parse_action(entity: _Entity) -> Action:
    parser = _PARSERS.get(entity.tag)
    if parser is None:
        raise FrontendError(f'<{entity.tag}> is not supported by this launch '
                            '(see docs/launch.md)')
    action = parser(entity)
    entity.check_all_used()
    return action


def _arg(entity: _Entity) -> Action:
    from launch.actions import DeclareLaunchArgument
    choices = [child.get('value', required=True) for child in _children(entity, 'choice')]
    return DeclareLaunchArgument(entity.get('name', required=True),
                                 default_value=_subs(entity, 'default'),
                                 description=entity.get('description'),
                                 choices=choices or None, **_condition(entity))


def _let(entity: _Entity) -> Action:
    from launch.actions import SetLaunchConfiguration
    return SetLaunchConfiguration(entity.get('name', required=True),
                                  _subs(entity, 'value', required=True), **_condition(entity))


def _include(entity: _Entity) -> Action:
    from launch.actions import IncludeLaunchDescription
    from launch.launch_description_sources import AnyLaunchDescriptionSource
    arguments = []
    for child in entity.children:
        if child.tag != 'arg':
            raise FrontendError(f'<include> holds <arg> elements only, got <{child.tag}>')
        arguments.append((child.get('name', required=True),
                          _subs(child, 'value', required=True)))
        child.check_all_used()
    return IncludeLaunchDescription(AnyLaunchDescriptionSource(_subs(entity, 'file', True)),
                                    launch_arguments=arguments, **_condition(entity))


def _group(entity: _Entity) -> Action:
    from launch.actions import GroupAction
    keep = {child.get('name', required=True): _subs(child, 'value', required=True)
            for child in _children(entity, 'keep')}
    actions = [_parse_action(child) for child in entity.children if child.tag != 'keep']
    return GroupAction(actions, scoped=_bool(entity, 'scoped', True),
                       forwarding=_bool(entity, 'forwarding', True),
                       launch_configurations=keep or None, **_condition(entity))


def _env_children(entity: _Entity) -> dict | None:
    env = {}
    for child in _children(entity, 'env'):
        env[tuple(_subs(child, 'name', True))] = _subs(child, 'value', True)
        child.check_all_used()
    return env or None


def _process_options(entity: _Entity) -> dict[str, Any]:
    options: dict[str, Any] = dict(_condition(entity))
    for attribute, key in (('output', 'output'), ('launch-prefix', 'prefix'),
                           ('launch_prefix', 'prefix'), ('cwd', 'cwd'),
                           ('sigterm_timeout', 'sigterm_timeout'),
                           ('sigkill_timeout', 'sigkill_timeout')):
        value = _subs(entity, attribute)
        if value is not None:
            options[key] = value
    if entity.get('respawn') is not None:
        options['respawn'] = parse_substitutions(entity.get('respawn'))
    if entity.get('respawn_delay') is not None:
        options['respawn_delay'] = float(entity.get('respawn_delay'))
    if entity.get('emulate_tty') is not None:
        options['emulate_tty'] = _bool(entity, 'emulate_tty', False)
    env = _env_children(entity)
    if env:
        options['additional_env'] = env
    return options


def _split_args(entity: _Entity, name: str) -> list[list[Substitution]] | None:
    value = entity.get(name)
    if value is None:
        return None
    return split_command_line(parse_substitutions(value))


def split_command_line(parts: list[Substitution]) -> list[list[Substitution]]:
    """Words of a command line, shell-like (quotes, spaces), substitutions kept whole."""
    words: list[list[Substitution]] = []
    word: list[Substitution] = []
    text = ''
    quote = ''
    started = False

    def flush_text() -> None:
        nonlocal text
        if text:
            word.append(TextSubstitution(text=text))
            text = ''

    for part in parts:
        if not isinstance(part, TextSubstitution):
            flush_text()
            word.append(part)
            started = True
            continue
        for char in part.text:
            if quote:
                if char == quote:
                    quote = ''
                else:
                    text += char
            elif char in '\'"':
                quote, started = char, True
            elif char.isspace():
                flush_text()
                if started:
                    words.append(word)
                word, started = [], False
            else:
                text += char
                started = True
    if quote:
        raise FrontendError(f'unterminated quote in command line: {quote}')
    flush_text()
    if started:
        words.append(word)
    return words


def _executable(entity: _Entity) -> Action:
    from launch.actions import ExecuteProcess
    cmd = _split_args(entity, 'cmd')
    if not cmd:
        raise FrontendError("<executable> needs the attribute 'cmd'")
    extra = _split_args(entity, 'args') or []
    return ExecuteProcess(cmd=cmd + extra, name=_subs(entity, 'name'),
                          shell=_bool(entity, 'shell', False), **_process_options(entity))


def _node(entity: _Entity) -> Action:
    from launch_ros.actions import Node
    parameters: list[Any] = []
    values: dict[str, Any] = {}
    for child in _children(entity, 'param'):
        if child.get('from') is not None:
            parameters.append(_subs(child, 'from'))
        else:
            value = child.get('value', required=True)
            values[child.get('name', required=True)] = (
                value if isinstance(value, (bool, int, float, list))
                else parse_substitutions(value))
        child.check_all_used()
    if values:
        parameters.insert(0, values)
    remappings = []
    for child in _children(entity, 'remap'):
        remappings.append((_subs(child, 'from', True), _subs(child, 'to', True)))
        child.check_all_used()
    for child in entity.children:
        if child.tag not in ('param', 'remap', 'env'):
            raise FrontendError(f'<node> cannot hold <{child.tag}>')
    namespace = entity.get('namespace', entity.get('ns'))
    return Node(package=_subs(entity, 'pkg'), executable=_subs(entity, 'exec', True),
                name=_subs(entity, 'name'),
                namespace=None if namespace is None else parse_substitutions(namespace),
                exec_name=_subs(entity, 'exec_name'),
                arguments=_split_args(entity, 'args'),
                ros_arguments=_split_args(entity, 'ros_args'),
                parameters=parameters or None, remappings=remappings or None,
                **_process_options(entity))


def _log(entity: _Entity) -> Action:
    from launch.actions import LogInfo
    return LogInfo(msg=_subs(entity, 'message', True), **_condition(entity))


def _timer(entity: _Entity) -> Action:
    from launch.actions import TimerAction
    return TimerAction(period=_subs(entity, 'period', True),
                       actions=_parse_children(entity), **_condition(entity))


def _shutdown(entity: _Entity) -> Action:
    from launch.actions import Shutdown
    return Shutdown(reason=_subs(entity, 'reason') or 'reason not given', **_condition(entity))


def _set_env(entity: _Entity) -> Action:
    from launch.actions import SetEnvironmentVariable
    return SetEnvironmentVariable(_subs(entity, 'name', True), _subs(entity, 'value', True),
                                  **_condition(entity))


def _unset_env(entity: _Entity) -> Action:
    from launch.actions import UnsetEnvironmentVariable
    return UnsetEnvironmentVariable(_subs(entity, 'name', True), **_condition(entity))


def _push_ns(entity: _Entity) -> Action:
    from launch_ros.actions import PushROSNamespace
    return PushROSNamespace(_subs(entity, 'namespace', True), **_condition(entity))


def _set_parameter(entity: _Entity) -> Action:
    from launch_ros.actions import SetParameter
    return SetParameter(entity.get('name', required=True), _subs(entity, 'value', True),
                        **_condition(entity))


def _set_remap(entity: _Entity) -> Action:
    from launch_ros.actions import SetRemap
    return SetRemap(_subs(entity, 'from', True), _subs(entity, 'to', True),
                    **_condition(entity))


_PARSERS: dict[str, Callable[[_Entity], Action]] = {
    'arg': _arg, 'let': _let, 'include': _include, 'group': _group, 'node': _node,
    'executable': _executable, 'log': _log, 'timer': _timer, 'shutdown': _shutdown,
    'set_env': _set_env, 'unset_env': _unset_env, 'push_ros_namespace': _push_ns,
    'set_parameter': _set_parameter, 'set_remap': _set_remap,
}
